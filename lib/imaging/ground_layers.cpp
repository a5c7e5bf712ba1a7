// The IGM and GLT of a scanner image (ground_layers.hpp; cube(5), GEOLOCATION LAYERS).
#include "imaging/ground_layers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.hpp"
#include "image/geolocation.hpp"
#include "image/image.hpp"
#include "image/layers.hpp"

namespace sigchain::imaging {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The median of the finite values (0 when none).
double median(std::vector<double> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !(x > 0); }), v.end());
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// Median distance between ground points `step` apart in the row-major grid, along rows
// (step 1) or columns (step = columns).
double median_spacing(const GroundGrid& g, bool along_rows) {
    std::vector<double> d;
    for (long r = 0; r + (along_rows ? 1 : 0) < g.rows; ++r)
        for (long c = 0; c + (along_rows ? 0 : 1) < g.columns; ++c) {
            const std::size_t i = static_cast<std::size_t>(r * g.columns + c);
            const std::size_t j = along_rows ? i + static_cast<std::size_t>(g.columns) : i + 1;
            d.push_back(
                std::hypot(g.map_xy[j][0] - g.map_xy[i][0], g.map_xy[j][1] - g.map_xy[i][1]));
        }
    return median(std::move(d));
}

GroundGrid ground_grid(const Sensor& sensor, const scene::Scene& scene,
                       const std::optional<GeoPlacement>& place, double mpu,
                       std::optional<double> plane, long row_begin, long row_end,
                       std::vector<std::array<double, 3>>* lon_lat_h) {
    GroundGrid g;
    g.rows = row_end - row_begin;
    g.columns = sensor.columns();
    g.scene = pixel_ground_points(sensor, scene, plane, row_begin, row_end);
    g.map_xy.assign(g.scene.size(), {kNan, kNan});
    std::optional<geo::MapProjector> map;
    if (place)
        map.emplace(place->map_crs, place->latitude_deg, place->longitude_deg, 0.0,
                    SourceLocation{"--crs", 0});
    if (lon_lat_h) lon_lat_h->assign(g.scene.size(), {kNan, kNan, kNan});
    for (std::size_t i = 0; i < g.scene.size(); ++i) {
        const geo::Vec3& p = g.scene[i];
        if (!std::isfinite(p[0])) continue;
        if (!map) {
            g.map_xy[i] = {p[0], p[1]};
            continue;
        }
        const geo::Vec3 m{p[0] * mpu, p[1] * mpu, p[2] * mpu};
        g.map_xy[i] = map->map_xy(m);
        if (lon_lat_h) (*lon_lat_h)[i] = map->lon_lat_height(m);
    }
    return g;
}

}  // namespace

Glt make_glt(const GroundGrid& g, const std::string& where) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const auto& p : g.map_xy)
        if (std::isfinite(p[0]))
            for (int k = 0; k < 2; ++k)
                lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double dr = median_spacing(g, true), dc = median_spacing(g, false);
    if (!(lo[0] <= hi[0]) || !(dr > 0) || !(dc > 0))
        throw DataError({where, 0}, "no pixel sees the ground: no geometry lookup table");
    Glt t;
    t.cell = std::sqrt(dr * dc);
    t.reach = std::max(dr, dc);
    t.x0 = std::floor(lo[0] / t.cell) * t.cell;
    t.y0 = std::ceil(hi[1] / t.cell) * t.cell;
    const double cols = std::ceil((hi[0] - t.x0) / t.cell) + 1,
                 rows = std::ceil((t.y0 - lo[1]) / t.cell) + 1;
    if (cols * rows > 64.0 * static_cast<double>(g.map_xy.size()) + 1e4)
        throw DataError({where, 0}, "the geometry lookup table would need " +
                                        std::to_string(static_cast<long>(cols * rows)) +
                                        " cells for a much smaller image: some pixels see the "
                                        "ground near the horizon");
    t.columns = static_cast<long>(cols);
    t.rows = static_cast<long>(rows);
    // Buckets of the grid's cells holding the pixels whose ground point falls in them.
    std::vector<std::vector<std::size_t>> bucket(static_cast<std::size_t>(t.rows * t.columns));
    const auto cell_of = [&](const std::array<double, 2>& p, long& cx, long& cy) {
        cx = static_cast<long>(std::floor((p[0] - t.x0) / t.cell));
        cy = static_cast<long>(std::floor((t.y0 - p[1]) / t.cell));
        return cx >= 0 && cy >= 0 && cx < t.columns && cy < t.rows;
    };
    for (std::size_t i = 0; i < g.map_xy.size(); ++i) {
        long cx = 0, cy = 0;
        if (std::isfinite(g.map_xy[i][0]) && cell_of(g.map_xy[i], cx, cy))
            bucket[static_cast<std::size_t>(cy * t.columns + cx)].push_back(i);
    }
    const long k = static_cast<long>(std::ceil(t.reach / t.cell));
    t.column.assign(bucket.size(), 0);
    t.row.assign(bucket.size(), 0);
    for (long cy = 0; cy < t.rows; ++cy)
        for (long cx = 0; cx < t.columns; ++cx) {
            const double x = t.x0 + (cx + 0.5) * t.cell, y = t.y0 - (cy + 0.5) * t.cell;
            double best = t.reach * t.reach;
            std::size_t found = SIZE_MAX;
            for (long by = std::max(0L, cy - k); by <= std::min(t.rows - 1, cy + k); ++by)
                for (long bx = std::max(0L, cx - k); bx <= std::min(t.columns - 1, cx + k); ++bx)
                    for (std::size_t i : bucket[static_cast<std::size_t>(by * t.columns + bx)]) {
                        const double ex = g.map_xy[i][0] - x, ey = g.map_xy[i][1] - y;
                        const double d2 = ex * ex + ey * ey;
                        if (d2 < best || (d2 == best && i < found)) best = d2, found = i;
                    }
            if (found == SIZE_MAX) continue;
            const std::size_t o = static_cast<std::size_t>(cy * t.columns + cx);
            t.column[o] = static_cast<double>(found % static_cast<std::size_t>(g.columns) + 1);
            t.row[o] = static_cast<double>(found / static_cast<std::size_t>(g.columns) + 1);
        }
    return t;
}

void write_ground_layers(const Sensor& sensor, const scene::Scene& scene,
                         const std::optional<GeoPlacement>& place, double mpu,
                         std::optional<double> plane, long row_begin, long row_end,
                         const std::string& igm_path, const std::string& glt_path,
                         std::string& note) {
    std::vector<std::array<double, 3>> llh;
    const GroundGrid g =
        ground_grid(sensor, scene, place, mpu, plane, row_begin, row_end, place ? &llh : nullptr);
    const std::string srs = place ? place->map_crs.wkt2() : "";
    const double nodata = image::kGeolocationNodata;
    const auto plane_of = [&](auto value) {
        std::vector<double> v(g.scene.size());
        for (std::size_t i = 0; i < v.size(); ++i) {
            const double x = value(i);
            v[i] = std::isfinite(x) ? x : nodata;
        }
        return v;
    };
    note.clear();
    if (!igm_path.empty()) {
        image::Layers igm;
        igm.rows = g.rows;
        igm.columns = g.columns;
        igm.srs_wkt = srs;
        igm.nodata = nodata;
        if (place) {
            igm.names = {"easting", "northing", "height (m)", "longitude (deg)", "latitude (deg)"};
            igm.planes = {plane_of([&](std::size_t i) { return g.map_xy[i][0]; }),
                          plane_of([&](std::size_t i) { return g.map_xy[i][1]; }),
                          plane_of([&](std::size_t i) { return llh[i][2]; }),
                          plane_of([&](std::size_t i) { return llh[i][0]; }),
                          plane_of([&](std::size_t i) { return llh[i][1]; })};
        }
        for (int k = 0; k < 3; ++k) {
            igm.names.push_back(std::string("scene ") + "xyz"[k]);
            igm.planes.push_back(plane_of([&](std::size_t i) { return g.scene[i][k]; }));
        }
        image::write_layers(igm_path, igm);
        note = "IGM: " + std::to_string(igm.planes.size()) + " layers to " + igm_path;
    }
    if (glt_path.empty()) return;
    const Glt t = make_glt(g, glt_path);
    image::Layers glt;
    glt.rows = t.rows;
    glt.columns = t.columns;
    glt.names = {"source column (1-based)", "source row (1-based)"};
    glt.planes = {t.column, t.row};
    glt.integer = true;
    glt.srs_wkt = srs;
    glt.nodata = 0;
    glt.geotransform = std::array<double, 6>{t.x0, t.cell, 0, t.y0, 0, -t.cell};
    image::write_layers(glt_path, glt);
    char buf[160];
    std::snprintf(buf, sizeof buf, "GLT: %ld x %ld cells of %.6g to %s", t.rows, t.columns, t.cell,
                  glt_path.c_str());
    note += (note.empty() ? "" : "; ") + std::string(buf);
}

}  // namespace sigchain::imaging
