// Geolocation arrays through GDAL (float64 GeoTIFF, GDAL's GEOLOCATION layout) and the
// ground control points drawn from them (cube(5), Georeferencing).
#include "image/geolocation.hpp"

#include <cpl_string.h>
#include <gdal_priv.h>

#include <algorithm>
#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "geo/crs.hpp"
#include "geo/gdal_dataset.hpp"
#include "image/gdal_output.hpp"

namespace sigchain::image {

using geo::gdal_init;
using geo::gdal_message;

std::string geolocation_name(const std::string& output_path) {
    return std::filesystem::path(output_path).replace_extension(".geoloc.tif").string();
}

std::string find_geolocation(const std::string& named, const std::string& image_path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (named.empty()) return named;
    const fs::path beside = fs::path(image_path).parent_path() / fs::path(named).filename();
    return fs::exists(beside, ec) ? beside.string() : named;
}

void write_geolocation(const std::string& path, const GeolocationArrays& a) {
    stage_geolocation(path, a)->commit();
}

std::unique_ptr<GdalOutput> stage_geolocation(const std::string& path,
                                              const GeolocationArrays& a) {
    gdal_init();
    const std::size_t n = static_cast<std::size_t>(a.rows) * static_cast<std::size_t>(a.columns);
    if (a.rows < 1 || a.columns < 1 || a.x.size() != n || a.y.size() != n)
        throw DataError({path, 0}, "geolocation arrays do not match the image's size");
    CPLStringList co;
    co.SetNameValue("INTERLEAVE", "BAND");
    auto staged = std::make_unique<GdalOutput>(path, "GTiff", a.columns, a.rows, 2, GDT_Float64,
                                               co.List());
    GdalOutput& out = *staged;
    // The arrays' own SRS: GDAL's SRC_GEOLOC_ARRAY transformer option reads it.
    out.dataset().SetProjection(a.srs_wkt.c_str());
    const std::vector<double>* planes[2] = {&a.x, &a.y};
    const char* names[2] = {"x (longitude)", "y (latitude)"};
    for (int b = 0; b < 2; ++b) {
        GDALRasterBand* band = out.dataset().GetRasterBand(b + 1);
        band->SetDescription(names[b]);
        band->SetNoDataValue(a.nodata);
        out.write_band(b + 1, GDT_Float64, planes[b]->data());
    }
    return staged;
}

GeolocationArrays read_geolocation(const std::string& path) {
    const geo::GdalDataset src = geo::open_dataset(path);
    if (!src || src->GetRasterCount() != 2)
        throw DataError({path, 0}, "not a geolocation array file (2 bands): " + gdal_message());
    GeolocationArrays a;
    a.rows = src->GetRasterYSize();
    a.columns = src->GetRasterXSize();
    const std::size_t n = static_cast<std::size_t>(a.rows) * static_cast<std::size_t>(a.columns);
    std::vector<double>* planes[2] = {&a.x, &a.y};
    for (int b = 0; b < 2; ++b) {
        planes[b]->resize(n);
        if (src->GetRasterBand(b + 1)->RasterIO(GF_Read, 0, 0, static_cast<int>(a.columns),
                                                static_cast<int>(a.rows), planes[b]->data(),
                                                static_cast<int>(a.columns),
                                                static_cast<int>(a.rows), GDT_Float64, 0, 0,
                                                nullptr) != CE_None)
            throw IoError(path + ": read error: " + gdal_message());
    }
    int has_nodata = 0;
    const double nodata = src->GetRasterBand(1)->GetNoDataValue(&has_nodata);
    if (has_nodata) a.nodata = nodata;
    const char* wkt = src->GetProjectionRef();
    a.srs_wkt = wkt ? wkt : "";
    return a;
}

std::vector<GroundControlPoint> gcp_lattice(const GeolocationArrays& a) {
    constexpr long kSteps = 16;  // 17 x 17 at most, as the map-grid fit's lattice
    std::vector<long> rows, columns;
    for (long i = 0; i <= kSteps; ++i) {
        rows.push_back((a.rows - 1) * i / kSteps);
        columns.push_back((a.columns - 1) * i / kSteps);
    }
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    std::vector<GroundControlPoint> gcps;
    for (long r : rows)
        for (long c : columns) {
            const std::size_t k = static_cast<std::size_t>(r) * a.columns + c;
            if (a.x[k] == a.nodata || a.y[k] == a.nodata) continue;
            gcps.push_back({c + 0.5, r + 0.5, a.x[k], a.y[k]});
        }
    return gcps;
}

}  // namespace sigchain::image
