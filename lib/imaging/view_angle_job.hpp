// The find_min_max_view_angle job (White (1996), section 4.2.3.3): the view-angle range
// of every ray of the sensor an .adv describes (make_sensor, as trace builds it: a frame
// camera, or a pushbroom or line scanner on its trajectory with its jitter) over a
// scene, by find_view_angles (view_angle.hpp); its report: the .snd line, the table of
// both methods, the --origin option.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "core/report.hpp"
#include "imaging/view_angle.hpp"
#include "scene/load.hpp"

namespace sigchain::imaging {

enum class ViewAngleMethod { BoundingBox, FieldOfView };

struct ViewAngleJob {
    std::string adv_path;
    std::string scene_path;         // .gdb, .odb, a mesh or a DEM raster (scene::assemble_scene)
    scene::SceneInput scene_input;  // the scene options (materials optional: geometry only)
    bool snd_line = false;          // print only the .snd line of `method`
    ViewAngleMethod method = ViewAngleMethod::FieldOfView;
    int grid = 256;  // interior rays per image axis (field-of-view)
    // The scene's geodetic origin (--origin): where DEM objects of an .odb and a
    // geodetic .trj (at height 0, as trace places it about the .snd's) are placed.
    // Without it a DEM given as the scene places itself (scene::lone_dem_origin).
    std::optional<scene::GeoOrigin> origin{};
};

// Runs the job and writes the report (or the .snd line) to `out`; the scene's warnings
// (a mesh file's degenerate facets skipped, coincident .odb instances) go to
// `reporter`, and with it verbose, the origin a lone DEM placed itself about. Throws
// DataError or IoError for bad inputs, including a field of view that misses the scene.
void run_view_angle_job(const ViewAngleJob& job, std::ostream& out,
                        const Reporter& reporter = Reporter());

// "LAT,LON" or "LAT,LON,HEIGHT" (deg north, deg east, metres above the WGS84
// ellipsoid) as an origin; throws UsageError naming `option` otherwise.
scene::GeoOrigin parse_geo_origin(const std::string& text, const std::string& option);

// Writes `report` to `out`: the .snd line of `method` (snd_line) or the table of both
// methods. Throws DataError (at `adv_path`) when the field-of-view method is asked for
// and no ray hits the scene in `scene_path`.
void write_view_angle_report(const ViewAngleReport& report, ViewAngleMethod method, bool snd_line,
                             const std::string& adv_path, const std::string& scene_path,
                             std::ostream& out);

// "a b c" rounded outward to the increment, as a .snd view-angle line.
std::string snd_view_angle_line(double min_deg, double max_deg, double increment_deg);

}  // namespace sigchain::imaging
