// Writing per-pixel layers as a GeoTIFF (layers.hpp).
#include "image/layers.hpp"

#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>

#include "core/error.hpp"
#include "geo/crs.hpp"
#include "image/gdal_output.hpp"

namespace sigchain::image {

void write_layers(const std::string& path, const Layers& layers) {
    geo::gdal_init();
    const std::size_t n = static_cast<std::size_t>(layers.rows) * layers.columns;
    if (layers.rows < 1 || layers.columns < 1 || layers.planes.empty() ||
        layers.names.size() != layers.planes.size())
        throw DataError({path, 0}, "layers do not match the image's size");
    for (const auto& p : layers.planes)
        if (p.size() != n) throw DataError({path, 0}, "layers do not match the image's size");
    CPLStringList co;
    co.SetNameValue("INTERLEAVE", "BAND");
    const GDALDataType type = layers.integer ? GDT_Int32 : GDT_Float64;
    GdalOutput out(path, "GTiff", layers.columns, layers.rows,
                   static_cast<int>(layers.planes.size()), type, co.List());
    if (!layers.srs_wkt.empty()) out.dataset().SetProjection(layers.srs_wkt.c_str());
    if (layers.geotransform) {
        std::array<double, 6> g = *layers.geotransform;
        out.dataset().SetGeoTransform(g.data());
    }
    for (std::size_t b = 0; b < layers.planes.size(); ++b) {
        GDALRasterBand* band = out.dataset().GetRasterBand(static_cast<int>(b) + 1);
        band->SetDescription(layers.names[b].c_str());
        if (layers.nodata) band->SetNoDataValue(*layers.nodata);
        out.write_band(static_cast<int>(b) + 1, GDT_Float64, layers.planes[b].data());
    }
    out.commit();
}

}  // namespace sigchain::image
