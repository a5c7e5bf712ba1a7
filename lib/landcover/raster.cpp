// Class rasters written as GeoTIFFs with GDAL.
#include "landcover/raster.hpp"

#include <stdexcept>

#include "core/error.hpp"
#include "image/gdal_output.hpp"

namespace sigchain::landcover {

void write_class_raster(const std::string& path, long rows, long columns,
                        const std::vector<int>& classes, const std::array<double, 6>& geotransform,
                        const geo::Crs& crs) {
    geo::gdal_init();
    if (classes.size() != static_cast<std::size_t>(rows * columns))
        throw std::invalid_argument("write_class_raster: size mismatch");
    image::GdalOutput out(path, "GTiff", columns, rows, 1, GDT_Byte, nullptr);
    std::array<double, 6> gt = geotransform;
    out.dataset().SetGeoTransform(gt.data());
    out.dataset().SetProjection(crs.wkt().c_str());
    const std::vector<unsigned char> bytes(classes.begin(), classes.end());
    out.write_band(1, GDT_Byte, bytes.data());
    out.commit();
}

}  // namespace sigchain::landcover
