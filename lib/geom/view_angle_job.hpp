// The find_min_max_view_angle job: load an .adv and a scene, report both methods.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "scene/load.hpp"

namespace sigchain::geom {

enum class ViewAngleMethod { BoundingBox, FieldOfView };

struct ViewAngleJob {
    std::string adv_path;
    std::string scene_path;  // .gdb, .odb, a mesh or a DEM raster (scene::assemble_scene)
    scene::SceneInput scene_input;  // a lone mesh's or DEM's materials
    bool snd_line = false;   // print only the .snd line of `method`
    ViewAngleMethod method = ViewAngleMethod::FieldOfView;
    int grid = 256;  // interior rays per image axis (field-of-view)
    // The scene's geodetic origin, needed by DEM objects in an .odb (--origin).
    std::optional<scene::GeoOrigin> origin{};
};

// "LAT,LON" or "LAT,LON,HEIGHT" (deg north, deg east, metres above the WGS84
// ellipsoid) as an origin; throws UsageError naming `option` otherwise.
scene::GeoOrigin parse_geo_origin(const std::string& text, const std::string& option);

// Runs the job and writes the report (or the .snd line) to `out`. Throws DataError
// or IoError for bad inputs, including a field of view that misses the scene.
void run_view_angle_job(const ViewAngleJob& job, std::ostream& out);

// "a b c" rounded outward to the increment, as a .snd view-angle line.
std::string snd_view_angle_line(double min_deg, double max_deg, double increment_deg);

}  // namespace sigchain::geom
