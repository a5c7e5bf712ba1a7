// Writing per-pixel layers as a GeoTIFF (layers.hpp).
#include "image/layers.hpp"

#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>

#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "core/output.hpp"
#include "geo/crs.hpp"

namespace sigchain::image {

void write_layers(const std::string& path, const Layers& layers) {
    geo::gdal_init();
    const std::size_t n = static_cast<std::size_t>(layers.rows) * layers.columns;
    if (layers.rows < 1 || layers.columns < 1 || layers.planes.empty() ||
        layers.names.size() != layers.planes.size())
        throw DataError({path, 0}, "layers do not match the image's size");
    for (const auto& p : layers.planes)
        if (p.size() != n) throw DataError({path, 0}, "layers do not match the image's size");
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    if (!driver) throw IoError(path + ": GDAL has no GTiff driver");
    const TempDir folder(path);
    const std::string temp = folder.file(std::filesystem::path(path).filename().string());
    CPLStringList co;
    co.SetNameValue("INTERLEAVE", "BAND");
    const GDALDataType type = layers.integer ? GDT_Int32 : GDT_Float64;
    std::unique_ptr<GDALDataset> ds(driver->Create(
        temp.c_str(), static_cast<int>(layers.columns), static_cast<int>(layers.rows),
        static_cast<int>(layers.planes.size()), type, co.List()));
    if (!ds) throw IoError(path + ": cannot create: " + geo::gdal_message());
    if (!layers.srs_wkt.empty()) ds->SetProjection(layers.srs_wkt.c_str());
    if (layers.geotransform) {
        std::array<double, 6> g = *layers.geotransform;
        ds->SetGeoTransform(g.data());
    }
    for (std::size_t b = 0; b < layers.planes.size(); ++b) {
        GDALRasterBand* band = ds->GetRasterBand(static_cast<int>(b) + 1);
        band->SetDescription(layers.names[b].c_str());
        if (layers.nodata) band->SetNoDataValue(*layers.nodata);
        if (band->RasterIO(
                GF_Write, 0, 0, static_cast<int>(layers.columns), static_cast<int>(layers.rows),
                const_cast<double*>(layers.planes[b].data()), static_cast<int>(layers.columns),
                static_cast<int>(layers.rows), GDT_Float64, 0, 0, nullptr) != CE_None)
            throw IoError(path + ": write error: " + geo::gdal_message());
    }
    CPLErrorReset();
    ds.reset();
    if (CPLGetLastErrorType() >= CE_Failure)
        throw IoError(path + ": write error: " + geo::gdal_message());
    commit_moves({{temp, path}});
}

}  // namespace sigchain::image
