// The find_min_max_view_angle job (White (1996), section 4.2.3.3): the view-angle range
// of every ray of the sensor an .adv describes (make_sensor, as trace builds it: a frame
// camera, or a pushbroom or line scanner on its trajectory with its jitter) over a scene.
// Here, above lib/geom, because the scanners' rays are trace's (sensor.hpp); the frame
// camera's range and the report are lib/geom's (view_angle.*, view_angle_job.*).
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "core/report.hpp"
#include "geom/view_angle.hpp"
#include "geom/view_angle_job.hpp"
#include "scene/load.hpp"
#include "trace/sensor.hpp"

namespace sigchain::trace {

struct ViewAngleJob {
    std::string adv_path;
    std::string scene_path;         // .gdb, .odb, a mesh or a DEM raster (scene::assemble_scene)
    scene::SceneInput scene_input;  // the scene options (materials optional: geometry only)
    bool snd_line = false;          // print only the .snd line of `method`
    geom::ViewAngleMethod method = geom::ViewAngleMethod::FieldOfView;
    int grid = 256;  // interior rays per image axis (field-of-view)
    // The scene's geodetic origin (--origin): where DEM objects of an .odb and a
    // geodetic .trj (at height 0, as trace places it about the .snd's) are placed.
    // Without it a DEM given as the scene places itself (scene::lone_dem_origin).
    std::optional<scene::GeoOrigin> origin{};
};

// Both methods for any sensor, as geom::find_view_angles does for a frame camera: the
// field-of-view method casts sensor.ray() through every border pixel centre, the four
// image corners and an interior grid of at most `grid` x `grid` positions, each ray's
// angle by sensor.view_angle_deg (world_view_angle_deg's for a ray that misses); the
// bounding-box method takes the scene box's corners from the origin of every border
// ray (a moving platform's positions over the image). Throws DataError if the scene is
// empty.
geom::ViewAngleReport find_view_angles(const Sensor& sensor, const scene::Scene& scene,
                                       int grid = 256);

// Runs the job and writes the report (or the .snd line) to `out`; the scene's warnings
// (a mesh file's degenerate facets skipped, coincident .odb instances) go to
// `reporter`, and with it verbose, the origin a lone DEM placed itself about. Throws
// DataError or IoError for bad inputs, including a field of view that misses the scene.
void run_view_angle_job(const ViewAngleJob& job, std::ostream& out,
                        const Reporter& reporter = Reporter());

}  // namespace sigchain::trace
