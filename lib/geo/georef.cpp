// Scene ENU -> WGS84 (GeographicLib) -> map CRS (GDAL/OGR), and the geotransform fit.
#include "geo/georef.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geo/gdal_dataset.hpp"

namespace sigchain::geo {

Crs crs_from_user(const std::string& text) {
    gdal_init();
    OGRSpatialReference srs;
    if (text.rfind("EPSG:", 0) == 0 || text.rfind("epsg:", 0) == 0) {
        if (srs.SetFromUserInput(text.c_str()) != OGRERR_NONE)
            throw UsageError("--crs " + text + ": unknown CRS: " + gdal_message());
        return Crs::from_ogr(&srs);
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(text, ec))
        throw UsageError("--crs " + text + ": expected EPSG:N or a WKT file (no such file)");
    std::ifstream in(text);
    std::ostringstream body;
    body << in.rdbuf();
    // gdalsrsinfo -o wkt starts its output with an empty line, which OGR rejects.
    std::string text_crs = body.str();
    text_crs.erase(0, text_crs.find_first_not_of(" \t\r\n"));
    if (srs.SetFromUserInput(text_crs.c_str()) != OGRERR_NONE || srs.IsEmpty())
        throw DataError({text, 1}, "not a coordinate reference system (WKT): " + gdal_message());
    return Crs::from_ogr(&srs);
}

Crs raster_crs(const std::string& path) {
    gdal_init();
    check_sidecars(path);
    const GdalDataset ds = open_dataset(path);
    if (!ds) throw IoError(path + ": cannot open: " + gdal_message());
    return Crs::from_ogr(ds->GetSpatialRef());
}

Crs wgs84_lon_lat() {
    gdal_init();
    OGRSpatialReference srs;
    srs.importFromEPSG(4326);
    return Crs::from_ogr(&srs);
}

std::string utm_epsg(double latitude_deg, double longitude_deg, const SourceLocation& where) {
    if (!(latitude_deg >= -90 && latitude_deg <= 90) || !std::isfinite(longitude_deg))
        throw DataError(where, "latitude " + std::to_string(latitude_deg) +
                                   " deg: no UTM or UPS zone (latitude in [-90, 90])");
    const int zone = GeographicLib::UTMUPS::StandardZone(latitude_deg, longitude_deg);
    const bool north = latitude_deg >= 0;
    // EPSG's WGS84 / UTM zone codes: 32601-32660 north, 32701-32760 south; UPS 32661/32761.
    const int code = zone == GeographicLib::UTMUPS::UPS ? (north ? 32661 : 32761)
                                                        : (north ? 32600 : 32700) + zone;
    return "EPSG:" + std::to_string(code);
}

struct MapProjector::Impl {
    GeographicLib::LocalCartesian enu;
    std::unique_ptr<OGRCoordinateTransformation> to_map;
    SourceLocation where;
};

MapProjector::MapProjector(const Crs& map, double origin_latitude_deg, double origin_longitude_deg,
                           double origin_height_m, const SourceLocation& where)
    : m_impl(std::make_unique<Impl>()) {
    gdal_init();
    m_impl->enu.Reset(origin_latitude_deg, origin_longitude_deg, origin_height_m);
    m_impl->where = where;
    if (map.empty()) throw DataError(where, "no map coordinate reference system");
    OGRSpatialReference wgs84, target(*map.ogr());
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);   // x = longitude
    target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = easting or longitude
    m_impl->to_map.reset(OGRCreateCoordinateTransformation(&wgs84, &target));
    if (!m_impl->to_map)
        throw DataError(where, "cannot transform WGS84 to the map CRS: " + gdal_message());
}

MapProjector::~MapProjector() = default;

std::array<double, 2> MapProjector::lon_lat(const Vec3& enu_m) const {
    double lat = 0, lon = 0, h = 0;
    m_impl->enu.Reverse(enu_m[0], enu_m[1], enu_m[2], lat, lon, h);
    return {lon, lat};
}

std::array<double, 3> MapProjector::lon_lat_height(const Vec3& enu_m) const {
    double lat = 0, lon = 0, h = 0;
    m_impl->enu.Reverse(enu_m[0], enu_m[1], enu_m[2], lat, lon, h);
    return {lon, lat, h};
}

std::array<double, 2> MapProjector::map_xy(const Vec3& enu_m) const {
    auto [x, y] = lon_lat(enu_m);
    int ok = 0;
    if (!m_impl->to_map->Transform(1, &x, &y, nullptr, &ok) || !ok)
        throw DataError(m_impl->where,
                        "cannot transform a point to the map CRS: " + gdal_message());
    return {x, y};
}

namespace {

// Solves the 3 x 3 system a p = b (Cramer's rule); false when singular.
bool solve3(const double a[3][3], const double b[3], double p[3]) {
    auto det = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    if (!(std::abs(d) > 1e-12)) return false;
    for (int k = 0; k < 3; ++k) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
        p[k] = det(m) / d;
    }
    return true;
}

}  // namespace

std::optional<GeoTransformFit> fit_geotransform(const std::vector<GridTie>& ties) {
    if (ties.size() < 3) return std::nullopt;
    // Centred coordinates keep the normal equations well conditioned (map coordinates
    // reach 1e7 m in UTM northings).
    double c0 = 0, r0 = 0, x0 = 0, y0 = 0;
    for (const GridTie& t : ties) {
        c0 += t.column;
        r0 += t.row;
        x0 += t.x;
        y0 += t.y;
    }
    const double n = static_cast<double>(ties.size());
    c0 /= n, r0 /= n, x0 /= n, y0 /= n;
    double a[3][3] = {}, bx[3] = {}, by[3] = {};
    for (const GridTie& t : ties) {
        const double v[3] = {1.0, t.column - c0, t.row - r0};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) a[i][j] += v[i] * v[j];
            bx[i] += v[i] * (t.x - x0);
            by[i] += v[i] * (t.y - y0);
        }
    }
    double px[3], py[3];
    if (!solve3(a, bx, px) || !solve3(a, by, py)) return std::nullopt;
    GeoTransformFit fit;
    GeoTransform& g = fit.geotransform;
    g = {x0 + px[0] - px[1] * c0 - px[2] * r0, px[1], px[2],
         y0 + py[0] - py[1] * c0 - py[2] * r0, py[1], py[2]};
    const double pixel = std::sqrt(std::abs(g[1] * g[5] - g[2] * g[4]));
    if (!(pixel > 0)) return std::nullopt;
    for (const GridTie& t : ties) {
        const double dx = g[0] + t.column * g[1] + t.row * g[2] - t.x;
        const double dy = g[3] + t.column * g[4] + t.row * g[5] - t.y;
        fit.max_residual_px = std::max(fit.max_residual_px, std::hypot(dx, dy) / pixel);
    }
    return fit;
}

}  // namespace sigchain::geo
