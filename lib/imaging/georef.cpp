// The georeferencing of trace's outputs: the map-grid fit and the geolocation arrays.
#include "imaging/georef.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "image/geolocation.hpp"
#include "scene/load.hpp"

namespace sigchain::imaging {

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

std::optional<GeoPlacement> geo_placement(const std::string& crs_option,
                                          const std::string& scene_path, const geo::LatLon& origin,
                                          double meters_per_unit, const std::string& snd_path,
                                          std::string& note) {
    note.clear();
    if (crs_option == "none") return std::nullopt;
    geo::Crs crs = crs_option.empty() ? scene::terrain_crs(scene_path)
                                      : geo::crs_from_user(crs_option);
    if (crs.empty()) {
        const std::string utm =
            geo::utm_epsg(origin.latitude_deg, origin.longitude_deg, {snd_path, 0});
        crs = geo::crs_from_user(utm);
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "map CRS %s, the UTM zone of the .snd's latitude %.6g and longitude %.6g: "
                      "the scene names none (--crs none: no georeferencing)",
                      utm.c_str(), origin.latitude_deg, origin.longitude_deg);
        note = buf;
    }
    return GeoPlacement{origin.latitude_deg, origin.longitude_deg, meters_per_unit, crs};
}

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
                                         long row_end, long total_rows,
                                         const std::string& arrays_path, std::string& note) {
    image::Georeference georef;
    // Fitted to the whole image, so that the parts of a render (--rows, --tile) agree
    // with it and with each other: row_begin 0 gives the whole's geotransform itself.
    const auto fit = fit_map_grid(sensor, place, 0, total_rows);
    char buf[160];
    if (fit && fit->max_residual_px < kGridAlignmentTolerancePx) {
        georef.geotransform = from_row(fit->geotransform, row_begin);
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
    image::GeolocationArrays arrays;
    arrays.rows = row_end - row_begin;
    arrays.columns = sensor.columns();
    arrays.x.assign(points.size(), image::kGeolocationNodata);
    arrays.y = arrays.x;
    arrays.srs_wkt = geo::wgs84_lon_lat().wkt();
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i][0])) continue;
        const auto ll = map.lon_lat(metres(points[i], place.meters_per_unit));
        arrays.x[i] = ll[0];
        arrays.y[i] = ll[1];
    }
    georef.geolocation_path = arrays_path;
    georef.gcps = image::gcp_lattice(arrays);
    georef.arrays = std::make_shared<const image::GeolocationArrays>(std::move(arrays));
    if (fit)
        std::snprintf(buf, sizeof buf,
                      "georeferencing: geolocation arrays and %zu ground control points (the "
                      "image grid is %.3g pixel off a map grid)",
                      georef.gcps.size(), fit->max_residual_px);
    else
        std::snprintf(buf, sizeof buf,
                      "georeferencing: geolocation arrays and %zu ground control points (the "
                      "image does not lie on a plane)",
                      georef.gcps.size());
    note = buf;
    return georef;
}

image::Georeference georeference_render(const Sensor& sensor, const scene::Scene& scene,
                                        const GeoPlacement& place, bool crs_named,
                                        std::optional<double> plane_height, long row_begin,
                                        long row_end, long total_rows,
                                        const std::string& arrays_path, const Reporter& reporter) {
    std::string note;
    image::Georeference georef;
    try {
        georef = georeference_outputs(sensor, scene, place, plane_height, row_begin, row_end,
                                      total_rows, arrays_path, note);
    } catch (const DataError& e) {
        if (crs_named) throw;
        reporter.warn(std::string("not georeferenced: ") + e.what() +
                      " (--crs names another map CRS)");
        return {};
    }
    reporter.info(note);
    return georef;
}

}  // namespace sigchain::imaging
