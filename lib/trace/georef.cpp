// The georeferencing of trace's outputs: the map-grid fit and the geolocation arrays.
#include "trace/georef.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace sigchain::trace {

namespace {

// Where a ray meets the horizontal plane z = height, or nothing (parallel or behind).
std::optional<geo::Vec3> plane_point(const geo::Vec3& origin, const geo::Vec3& dir, double height) {
    if (!(std::abs(dir[2]) > 1e-12)) return std::nullopt;
    const double t = (height - origin[2]) / dir[2];
    if (!(t > 0)) return std::nullopt;
    return geo::Vec3{origin[0] + t * dir[0], origin[1] + t * dir[1], height};
}

geo::Vec3 metres(const geo::Vec3& p, double meters_per_unit) {
    return {p[0] * meters_per_unit, p[1] * meters_per_unit, p[2] * meters_per_unit};
}

}  // namespace

std::optional<geo::GeoTransformFit> fit_map_grid(const Sensor& sensor, const GeoPlacement& place,
                                                 long row_begin, long row_end) {
    const geo::MapProjector map(place.map_crs, place.latitude_deg, place.longitude_deg, 0.0,
                                {"--crs", 0});
    constexpr int kSteps = 16;  // 17 x 17 ties: corners, edges and the interior
    std::vector<geo::GridTie> ties;
    const double rows = static_cast<double>(row_end - row_begin);
    const double columns = static_cast<double>(sensor.columns());
    for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; j <= kSteps; ++j) {
            const double row = rows * i / kSteps, column = columns * j / kSteps;
            geo::Vec3 origin{}, dir{};
            sensor.nominal_ray(row + static_cast<double>(row_begin), column, origin, dir);
            const auto p = plane_point(origin, dir, 0.0);
            if (!p) return std::nullopt;
            const auto xy = map.map_xy(metres(*p, place.meters_per_unit));
            ties.push_back({column, row, xy[0], xy[1]});
        }
    return geo::fit_geotransform(ties);
}

std::vector<geo::Vec3> pixel_ground_points(const Sensor& sensor, const scene::Scene& scene,
                                           std::optional<double> plane_height, long row_begin,
                                           long row_end) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<geo::Vec3> points;
    points.reserve(static_cast<std::size_t>(row_end - row_begin) * sensor.columns());
    for (long r = row_begin; r < row_end; ++r)
        for (long c = 0; c < sensor.columns(); ++c) {
            geo::Vec3 origin{}, dir{};
            sensor.ray(r + 0.5, c + 0.5, origin, dir);
            if (const auto hit = scene.intersect(origin, dir)) {
                const double t = hit->distance;
                points.push_back(
                    {origin[0] + t * dir[0], origin[1] + t * dir[1], origin[2] + t * dir[2]});
                continue;
            }
            std::optional<geo::Vec3> p;
            if (plane_height && dir[2] < 0) p = plane_point(origin, dir, *plane_height);
            points.push_back(p ? *p : geo::Vec3{nan, nan, nan});
        }
    return points;
}

image::Georeference georeference_outputs(const Sensor& sensor, const scene::Scene& scene,
                                         const GeoPlacement& place,
                                         std::optional<double> plane_height, long row_begin,
                                         long row_end, const std::string& arrays_path,
                                         std::string& note) {
    image::Georeference georef;
    const auto fit = fit_map_grid(sensor, place, row_begin, row_end);
    char buf[160];
    if (fit && fit->max_residual_px < kGridAlignmentTolerancePx) {
        georef.geotransform = fit->geotransform;
        georef.crs_wkt = place.map_crs.wkt2();
        std::snprintf(buf, sizeof buf,
                      "georeferencing: a geotransform (the image grid is within %.2g pixel of "
                      "the map grid)",
                      fit->max_residual_px);
        note = buf;
        return georef;
    }
    const geo::MapProjector map(place.map_crs, place.latitude_deg, place.longitude_deg, 0.0,
                                {"--crs", 0});
    const auto points = pixel_ground_points(sensor, scene, plane_height, row_begin, row_end);
    std::vector<double> x(points.size(), image::kGeolocationNodata), y = x;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i][0])) continue;
        const auto ll = map.lon_lat(metres(points[i], place.meters_per_unit));
        x[i] = ll[0];
        y[i] = ll[1];
    }
    image::write_geolocation(arrays_path, row_end - row_begin, sensor.columns(), x, y,
                             geo::wgs84_lon_lat().wkt(), image::kGeolocationNodata);
    georef.geolocation_path = arrays_path;
    if (fit)
        std::snprintf(buf, sizeof buf,
                      "georeferencing: geolocation arrays (the image grid is %.3g pixel off "
                      "a map grid)",
                      fit->max_residual_px);
    else
        std::snprintf(buf, sizeof buf,
                      "georeferencing: geolocation arrays (the image does not lie on a plane)");
    note = buf;
    return georef;
}

}  // namespace sigchain::trace
