// GDAL/OGR access for land-cover rasters (read, write a class GeoTIFF, place on WGS84).
#include "landcover/raster.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <unistd.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "core/error.hpp"
#include "image/gdal.hpp"

namespace sigchain::landcover {
namespace {

struct DatasetCloser {
    void operator()(GDALDataset* ds) const { GDALClose(ds); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

void read_band(GDALDataset& ds, int band, GeoRaster& r) {
    double* dst = r.values.data() + static_cast<std::size_t>(band) * r.rows * r.columns;
    CPLErr err = ds.GetRasterBand(band + 1)->RasterIO(
        GF_Read, 0, 0, static_cast<int>(r.columns), static_cast<int>(r.rows), dst,
        static_cast<int>(r.columns), static_cast<int>(r.rows), GDT_Float64, 0, 0);
    if (err != CE_None) throw IoError(ds.GetDescription() + std::string(": ") + image::gdal_message());
}

// Transforms (x, y) in `wkt` to WGS84 (lat, lon) in degrees, traditional axis order.
std::array<double, 2> to_wgs84(const std::string& wkt, double x, double y) {
    OGRSpatialReference src;
    OGRSpatialReference dst;
    src.importFromWkt(wkt.c_str());
    src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    dst.SetWellKnownGeogCS("WGS84");
    dst.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&src, &dst));
    if (!ct || !ct->Transform(1, &x, &y)) throw DataError({"", 0}, "cannot transform to WGS84");
    return {y, x};
}

}  // namespace

GeoRaster read_geo_raster(const std::string& path) {
    image::gdal_init();
    Dataset ds(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!ds) throw IoError(path + ": " + image::gdal_message());
    GeoRaster r;
    r.rows = ds->GetRasterYSize();
    r.columns = ds->GetRasterXSize();
    r.bands = ds->GetRasterCount();
    if (ds->GetGeoTransform(r.geotransform.data()) != CE_None)
        throw DataError({path, 0}, "raster has no geotransform");
    if (r.geotransform[2] != 0 || r.geotransform[4] != 0)
        throw DataError({path, 0}, "rotated raster grids are not supported");
    const OGRSpatialReference* srs = ds->GetSpatialRef();
    if (!srs) throw DataError({path, 0}, "raster has no coordinate reference system");
    char* wkt = nullptr;
    srs->exportToWkt(&wkt);
    r.crs_wkt = wkt;
    CPLFree(wkt);
    r.values.resize(static_cast<std::size_t>(r.bands) * r.rows * r.columns);
    for (int b = 0; b < r.bands; ++b) read_band(*ds, b, r);
    return r;
}

void write_class_raster(const std::string& path, long rows, long columns,
                        const std::vector<int>& classes,
                        const std::array<double, 6>& geotransform, const std::string& crs_wkt) {
    image::gdal_init();
    if (classes.size() != static_cast<std::size_t>(rows * columns))
        throw std::invalid_argument("write_class_raster: size mismatch");
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
    const std::string tmp = path + ".tmp." + std::to_string(getpid());
    {
        Dataset ds(drv->Create(tmp.c_str(), static_cast<int>(columns), static_cast<int>(rows), 1,
                               GDT_Byte, nullptr));
        if (!ds) throw IoError(path + ": " + image::gdal_message());
        std::array<double, 6> gt = geotransform;
        ds->SetGeoTransform(gt.data());
        ds->SetProjection(crs_wkt.c_str());
        std::vector<unsigned char> bytes(classes.begin(), classes.end());
        if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, static_cast<int>(columns),
                                           static_cast<int>(rows), bytes.data(),
                                           static_cast<int>(columns), static_cast<int>(rows),
                                           GDT_Byte, 0, 0) != CE_None)
            throw IoError(path + ": " + image::gdal_message());
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw IoError(path + ": cannot rename");
}

RasterPlacement raster_placement(const GeoRaster& raster) {
    const auto& g = raster.geotransform;
    const double xc = g[0] + g[1] * raster.columns / 2.0;
    const double yc = g[3] + g[5] * raster.rows / 2.0;
    const auto centre = to_wgs84(raster.crs_wkt, xc, yc);
    const auto east = to_wgs84(raster.crs_wkt, xc + 1000.0, yc);
    GeographicLib::LocalCartesian enu(centre[0], centre[1], 0.0);
    double e = 0, n = 0, u = 0;
    enu.Forward(east[0], east[1], 0.0, e, n, u);
    return {centre[0], centre[1], std::atan2(n, e) * 180.0 / std::numbers::pi};
}

}  // namespace sigchain::landcover
