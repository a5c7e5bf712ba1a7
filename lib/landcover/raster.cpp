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

void write_class_raster(const std::string& path, long rows, long columns,
                        const std::vector<int>& classes, const std::array<double, 6>& geotransform,
                        const geo::Crs& crs) {
    geo::gdal_init();
    if (classes.size() != static_cast<std::size_t>(rows * columns))
        throw std::invalid_argument("write_class_raster: size mismatch");
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
    // GDAL opens its file itself: it goes into a private folder beside the target.
    const TempDir folder(path);
    const std::string tmp = folder.file(std::filesystem::path(path).filename().string());
    std::unique_ptr<GDALDataset> ds(drv->Create(tmp.c_str(), static_cast<int>(columns),
                                                static_cast<int>(rows), 1, GDT_Byte, nullptr));
    if (!ds) throw IoError(path + ": " + geo::gdal_message());
    std::array<double, 6> gt = geotransform;
    ds->SetGeoTransform(gt.data());
    ds->SetProjection(crs.wkt().c_str());
    std::vector<unsigned char> bytes(classes.begin(), classes.end());
    if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, static_cast<int>(columns),
                                       static_cast<int>(rows), bytes.data(),
                                       static_cast<int>(columns), static_cast<int>(rows), GDT_Byte,
                                       0, 0) != CE_None)
        throw IoError(path + ": " + geo::gdal_message());
    // Closing flushes the data: a failure there (a full disk) is a write error too.
    CPLErrorReset();
    ds.reset();
    if (CPLGetLastErrorType() >= CE_Failure) throw IoError(path + ": write error: " + geo::gdal_message());
    commit_moves({{tmp, path}});
}

}  // namespace sigchain::landcover
