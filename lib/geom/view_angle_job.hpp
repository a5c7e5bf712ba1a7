// find_min_max_view_angle's report: the .snd line, the table of both methods, the
// --origin option. The Job itself (the sensor an .adv describes, through trace's
// make_sensor) is lib/trace/view_angle_job.*.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "geom/view_angle.hpp"
#include "scene/load.hpp"

namespace sigchain::geom {

enum class ViewAngleMethod { BoundingBox, FieldOfView };

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

}  // namespace sigchain::geom
