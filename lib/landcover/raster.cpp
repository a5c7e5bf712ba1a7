// Class rasters written as GeoTIFFs with GDAL.
#include "landcover/raster.hpp"

#include <gdal_priv.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "core/error.hpp"
#include "core/output.hpp"

namespace sigchain::landcover {

namespace {

struct DatasetCloser {
    void operator()(GDALDataset* ds) const { GDALClose(ds); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

}  // namespace

namespace {

// One band of `type` from `bytes` (rows x columns of that type), atomically.
void write_band(const std::string& path, long rows, long columns, GDALDataType type,
                void* bytes, const std::array<double, 6>& geotransform, const geo::Crs& crs) {
    geo::gdal_init();
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
    // GDAL opens its file itself: it goes into a private folder beside the target.
    const TempDir folder(path);
    const std::string tmp = folder.file(std::filesystem::path(path).filename().string());
    {
        Dataset ds(drv->Create(tmp.c_str(), static_cast<int>(columns), static_cast<int>(rows), 1,
                               type, nullptr));
        if (!ds) throw IoError(path + ": " + geo::gdal_message());
        std::array<double, 6> gt = geotransform;
        ds->SetGeoTransform(gt.data());
        ds->SetProjection(crs.wkt().c_str());
        if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, static_cast<int>(columns),
                                           static_cast<int>(rows), bytes,
                                           static_cast<int>(columns), static_cast<int>(rows),
                                           type, 0, 0) != CE_None)
            throw IoError(path + ": " + geo::gdal_message());
    }
    commit_moves({{tmp, path}});
}

}  // namespace

void write_class_raster(const std::string& path, long rows, long columns,
                        const std::vector<int>& classes, const std::array<double, 6>& geotransform,
                        const geo::Crs& crs) {
    if (classes.size() != static_cast<std::size_t>(rows * columns))
        throw std::invalid_argument("write_class_raster: size mismatch");
    std::vector<unsigned char> bytes(classes.begin(), classes.end());
    write_band(path, rows, columns, GDT_Byte, bytes.data(), geotransform, crs);
}

void write_float_raster(const std::string& path, long rows, long columns,
                        const std::vector<double>& values,
                        const std::array<double, 6>& geotransform, const geo::Crs& crs) {
    if (values.size() != static_cast<std::size_t>(rows * columns))
        throw std::invalid_argument("write_float_raster: size mismatch");
    std::vector<double> copy = values;
    write_band(path, rows, columns, GDT_Float64, copy.data(), geotransform, crs);
}

}  // namespace sigchain::landcover
