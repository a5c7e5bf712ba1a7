// CRS -> WGS84 (GDAL/OGR) -> local east-north-up (GeographicLib), and GDAL's set-up.
#include "geo/crs.hpp"

#include <cpl_conv.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <system_error>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace sigchain::geo {

void gdal_init() {
    static std::once_flag once;
    std::call_once(once, [] {
        CPLSetErrorHandler(CPLQuietErrorHandler);
        CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");
        GDALAllRegister();
    });
}

std::string gdal_message() {
    const char* m = CPLGetLastErrorMsg();
    return (m && *m) ? std::string(m) : std::string("unknown GDAL error");
}

void check_sidecars(const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path raster(path);
    std::vector<std::pair<fs::path, bool>> sides;  // (side file, holds text)
    for (const char* ext : {".prj", ".hdr", ".aux.xml", ".tfw", ".wld", ".aux", ".PRJ", ".HDR",
                            ".TFW", ".WLD"})
        sides.emplace_back(fs::path(raster).replace_extension(ext), true);
    sides.emplace_back(fs::path(raster).replace_extension(".ovr"), false);
    sides.emplace_back(fs::path(path + ".aux.xml"), true);
    sides.emplace_back(fs::path(path + ".ovr"), false);
    for (const auto& [side, text] : sides) {
        if (side == raster) continue;  // the raster itself (an ENVI .hdr given as the cube)
        std::error_code ec;
        const auto status = fs::status(side, ec);
        if (ec || !fs::exists(status)) continue;
        if (!fs::is_regular_file(status))
            throw DataError({side.string(), 0}, "not a regular file (a side file GDAL would "
                                                "read with " + path + ")");
        const auto bytes = fs::file_size(side, ec);
        if (text && !ec && static_cast<long long>(bytes) > kMaxSidecarBytes)
            throw DataError({side.string(), 0},
                            std::to_string(bytes) + " bytes: larger than a side file of " + path +
                                " may be (" + std::to_string(kMaxSidecarBytes >> 20) + " MiB)");
    }
}

void require_crs(const Crs& crs, const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    if (!crs.empty()) return;
    for (const char* ext : {".prj", ".PRJ"}) {
        const fs::path prj = fs::path(path).replace_extension(ext);
        std::error_code ec;
        if (prj == fs::path(path) || !fs::is_regular_file(prj, ec)) continue;
        std::ifstream in(prj, std::ios::binary);  // at most 16 MiB (check_sidecars)
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        const std::string why = " (so " + path + " has none)";
        if (text.find_first_not_of(" \t\r\n") == std::string::npos)
            throw DataError({prj.string(), 0}, "the file is empty" + why);
        OGRSpatialReference srs;
        CPLErrorReset();
        if (srs.SetFromUserInput(text.c_str()) != OGRERR_NONE || srs.IsEmpty())
            throw DataError({prj.string(), 0},
                            "not a coordinate reference system GDAL reads (ESRI or OGC WKT): " +
                                gdal_message() + why);
        throw DataError({prj.string(), 0},
                        "a coordinate reference system, but GDAL's driver for " + path +
                            " does not take it" + why);
    }
    throw DataError({path, 0}, what + " has no coordinate reference system");
}

Crs Crs::from_ogr(const OGRSpatialReference* srs) {
    Crs crs;
    if (srs && !srs->IsEmpty()) crs.m_srs = std::make_shared<const OGRSpatialReference>(*srs);
    return crs;
}

Crs Crs::from_wkt(const std::string& wkt, const SourceLocation& where) {
    auto srs = std::make_shared<OGRSpatialReference>();
    if (srs->importFromWkt(wkt.c_str()) != OGRERR_NONE)
        throw DataError(where, "not a coordinate reference system (WKT): " + gdal_message());
    Crs crs;
    crs.m_srs = std::move(srs);
    return crs;
}

std::string Crs::wkt() const {
    if (!m_srs) return "";
    char* text = nullptr;
    m_srs->exportToWkt(&text);
    std::string out = text ? text : "";
    CPLFree(text);
    return out;
}

std::string Crs::wkt2() const {
    if (!m_srs) return "";
    char* text = nullptr;
    const char* options[] = {"FORMAT=WKT2_2019", nullptr};
    m_srs->exportToWkt(&text, options);
    std::string out = text ? text : "";
    CPLFree(text);
    return out;
}

bool Crs::same_as(const Crs& other) const {
    if (!m_srs || !other.m_srs) return !m_srs && !other.m_srs;
    return m_srs->IsSame(other.m_srs.get());
}

Wgs84Transform::Wgs84Transform(const Crs& from, const SourceLocation& where) : m_where(where) {
    if (from.empty()) throw DataError(where, "no coordinate reference system");
    OGRSpatialReference src(*from.ogr()), wgs84;
    src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = easting or longitude
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    m_transform.reset(OGRCreateCoordinateTransformation(&src, &wgs84));
    if (!m_transform)
        throw DataError(where, "cannot transform the CRS to WGS84: " + gdal_message());
}

Wgs84Transform::~Wgs84Transform() = default;

bool Wgs84Transform::transform(std::size_t n, double* x, double* y, int* ok) const {
    return m_transform->Transform(n, x, y, nullptr, ok) != 0;
}

LatLon Wgs84Transform::lat_lon(double x, double y) const {
    int ok = 0;
    if (!transform(1, &x, &y, &ok) || !ok)
        throw DataError(m_where, "cannot transform a point to WGS84: " + gdal_message());
    return {y, x};
}

}  // namespace sigchain::geo
