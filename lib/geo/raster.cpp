// GDAL geo-raster reading, and a raster's placement on WGS84.
#include "geo/raster.hpp"

#include <gdal_priv.h>
#include <unistd.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/gdal_dataset.hpp"

namespace sigchain::geo {

namespace {

void read_band(GDALDataset& ds, int band, GeoRaster& r, const std::string& path) {
    double* dst = r.values.data() + static_cast<std::size_t>(band) * r.rows * r.columns;
    const int rows = static_cast<int>(r.rows), columns = static_cast<int>(r.columns);
    if (ds.GetRasterBand(band + 1)->RasterIO(GF_Read, 0, 0, columns, rows, dst, columns, rows,
                                             GDT_Float64, 0, 0) != CE_None)
        throw IoError(path + ": read error: " + gdal_message());
}

// The machine's physical memory, bytes (0 when unknown).
double physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

std::string gib(double bytes) {
    const double g = bytes / (1024.0 * 1024.0 * 1024.0);
    return format_number(std::round(g * 10) / 10) + " GiB";
}

}  // namespace

bool GeoRaster::valid(double v) const { return std::isfinite(v) && !(nodata && v == *nodata); }

// The errors below name the file without a line: a raster is binary.
GeoRaster read_geo_raster(const std::string& path, Bands bands, double use_bytes_per_cell,
                          const char* use) {
    gdal_init();
    check_sidecars(path);
    const GdalDataset ds = open_dataset(path);
    if (!ds) throw IoError(path + ": cannot open the raster: " + gdal_message());
    if (ds->GetRasterCount() < 1) throw DataError({path, 0}, "the raster has no band");
    GeoRaster r;
    if (ds->GetGeoTransform(r.geotransform.data()) != CE_None)
        throw DataError({path, 0}, "the raster has no geotransform (not geo-referenced)");
    r.rows = ds->GetRasterYSize();
    r.columns = ds->GetRasterXSize();
    r.bands = bands == Bands::All ? ds->GetRasterCount() : bands == Bands::First ? 1 : 0;
    r.crs = Crs::from_ogr(ds->GetSpatialRef());
    int has_nodata = 0;
    const double nodata = ds->GetRasterBand(1)->GetNoDataValue(&has_nodata);
    if (has_nodata) r.nodata = nodata;
    // Refused before allocating: an out-of-memory error would name nothing.
    const double cells = static_cast<double>(r.rows) * static_cast<double>(r.columns);
    const double need = cells * (r.bands * sizeof(double) + use_bytes_per_cell);
    const double have = physical_memory_bytes();
    if (have > 0 && need > have)
        throw DataError({path, 0}, std::to_string(r.columns) + " x " + std::to_string(r.rows) +
                                       " cells need about " + gib(need) +
                                       (use_bytes_per_cell > 0 ? std::string(" ") + use : "") +
                                       ", more than this machine's " + gib(have) +
                                       " of memory: crop it (gdal_translate -srcwin) or "
                                       "coarsen it (gdalwarp -tr)");
    r.values.resize(static_cast<std::size_t>(r.bands) * r.rows * r.columns);
    for (int b = 0; b < r.bands; ++b) read_band(*ds, b, r, path);
    return r;
}

void require_north_up_with_crs(const GeoRaster& raster, const std::string& path) {
    if (raster.geotransform[2] != 0 || raster.geotransform[4] != 0)
        throw DataError({path, 0}, "rotated raster grids are not supported");
    require_crs(raster.crs, path, "the raster");
}

RasterPlacement raster_placement(const GeoRaster& raster, const std::string& path) {
    const auto& g = raster.geotransform;
    const double xc = g[0] + g[1] * raster.columns / 2.0;
    const double yc = g[3] + g[5] * raster.rows / 2.0;
    const Wgs84Transform to_wgs84(raster.crs, {path, 0});
    const LatLon centre = to_wgs84.lat_lon(xc, yc);
    const LatLon east = to_wgs84.lat_lon(xc + 1000.0, yc);
    const LocalEnu enu(centre.latitude_deg, centre.longitude_deg, 0.0);
    const Vec3 e = enu.forward(east.latitude_deg, east.longitude_deg, 0.0);
    return {centre.latitude_deg, centre.longitude_deg,
            std::atan2(e[1], e[0]) * 180.0 / std::numbers::pi};
}

}  // namespace sigchain::geo
