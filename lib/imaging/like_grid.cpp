// trace --like: a sensor on a raster's map grid (like_grid.hpp).
#include "imaging/like_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "geo/crs.hpp"
#include "geo/raster.hpp"

namespace sigchain::imaging {

LikeGrid read_like_grid(const std::string& path) {
    const geo::GeoRaster raster = geo::read_geo_raster(path, geo::Bands::None);
    if (raster.crs.empty())
        throw DataError({path, 0}, "--like: the raster names no coordinate reference system");
    return {raster.crs, raster.geotransform, raster.rows, raster.columns};
}

namespace {

class GridSensor final : public Sensor {
public:
    GridSensor(std::unique_ptr<Sensor> frame, const LikeGrid& grid, const GeoPlacement& place,
               const scene::Scene& scene, double plane_height)
        : m_frame(std::move(frame)),
          m_rows(grid.rows),
          m_columns(grid.columns),
          m_scene(scene),
          m_plane_height(plane_height),
          m_top(scene.bounds().upper[2] + 1.0) {
        if (!dynamic_cast<const FrameSensor*>(m_frame.get()))
            throw DataError({"--like", 0}, "renders a frame camera's view, not a " +
                                               m_frame->kind() + "'s");
        geo::Vec3 direction{};
        m_frame->ray(0.5, 0.5, m_position, direction);
        // The cell corners' map coordinates to WGS84 in one call, then to the scene's
        // east-north-up frame at height 0 (the frame is flat: only the height of a far
        // corner carries the Earth's curvature, d^2 / 2R).
        const geo::GeoTransform& g = grid.geotransform;
        const std::size_t n = static_cast<std::size_t>((m_rows + 1) * (m_columns + 1));
        std::vector<double> x, y;
        x.reserve(n);
        y.reserve(n);
        for (long r = 0; r <= m_rows; ++r)
            for (long c = 0; c <= m_columns; ++c) {
                x.push_back(g[0] + c * g[1] + r * g[2]);
                y.push_back(g[3] + c * g[4] + r * g[5]);
            }
        const geo::Wgs84Transform to_wgs84(grid.crs, {"--like", 0});
        std::vector<int> ok(n, 0);
        if (!to_wgs84.transform(n, x.data(), y.data(), ok.data()) ||
            std::find(ok.begin(), ok.end(), 0) != ok.end())
            throw DataError({"--like", 0}, "a corner of the raster's grid has no WGS84 position");
        const geo::LocalEnu enu(place.latitude_deg, place.longitude_deg, 0.0);
        m_corners.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            const geo::Vec3 p = enu.forward(y[i], x[i], 0.0);
            m_corners.push_back({p[0] / place.meters_per_unit, p[1] / place.meters_per_unit});
        }
    }
    long rows() const override { return m_rows; }
    long columns() const override { return m_columns; }
    void ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const override {
        // Bilinear in the cell's corners (clamped to the grid).
        const double rc = std::clamp(row, 0.0, static_cast<double>(m_rows));
        const double cc = std::clamp(column, 0.0, static_cast<double>(m_columns));
        const long r0 = std::min(static_cast<long>(rc), m_rows - 1);
        const long c0 = std::min(static_cast<long>(cc), m_columns - 1);
        const double u = cc - c0, v = rc - r0;
        const auto at = [&](long r, long c) { return m_corners[r * (m_columns + 1) + c]; };
        const auto a = at(r0, c0), b = at(r0, c0 + 1), c = at(r0 + 1, c0), d = at(r0 + 1, c0 + 1);
        const double e = (1 - v) * ((1 - u) * a[0] + u * b[0]) + v * ((1 - u) * c[0] + u * d[0]);
        const double n = (1 - v) * ((1 - u) * a[1] + u * b[1]) + v * ((1 - u) * c[1] + u * d[1]);
        // The top surface there: the first hit of a vertical ray from above the scene.
        double z = m_plane_height;
        if (const auto hit = m_scene.intersect({e, n, m_top}, {0, 0, -1})) z = m_top - hit->distance;
        const geo::Vec3 to{e - m_position[0], n - m_position[1], z - m_position[2]};
        const double len = std::sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
        origin = m_position;
        direction = {to[0] / len, to[1] / len, to[2] / len};
    }
    double view_angle_deg(const geo::Vec3& direction) const override {
        return m_frame->view_angle_deg(direction);
    }
    geo::Vec3 view_angle_reference() const override { return m_frame->view_angle_reference(); }
    std::string kind() const override { return "frame camera"; }
    std::string summary() const override {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "frame camera position on a map grid of %ld x %ld cells (--like)", m_rows,
                      m_columns);
        return buf;
    }

private:
    std::unique_ptr<Sensor> m_frame;
    long m_rows, m_columns;
    const scene::Scene& m_scene;
    double m_plane_height, m_top;
    geo::Vec3 m_position{};
    std::vector<std::array<double, 2>> m_corners;  // (rows + 1) x (columns + 1), scene units
};

}  // namespace

image::Georeference like_georeference(const LikeGrid& grid, long row_begin) {
    image::Georeference georef;
    georef.geotransform = from_row(grid.geotransform, row_begin);
    georef.crs_wkt = grid.crs.wkt2();
    return georef;
}

std::unique_ptr<Sensor> make_grid_sensor(std::unique_ptr<Sensor> frame, const LikeGrid& grid,
                                         const GeoPlacement& place, const scene::Scene& scene,
                                         double plane_height) {
    return std::make_unique<GridSensor>(std::move(frame), grid, place, scene, plane_height);
}

}  // namespace sigchain::imaging
