// DIRSIG texture maps (White (1996), section 5.2.5.3): a raster of .ems curve numbers over the scene.
#include <gdal_priv.h>

#include <cmath>

#include "core/error.hpp"
#include "geo/crs.hpp"
#include "geo/gdal_dataset.hpp"
#include "radiometry/material.hpp"

namespace sigchain::radiometry {

namespace {

[[noreturn]] void texture_error(const MaterialOptics& m, const std::string& what) {
    std::string message = "material '" + m.name + "' (" + std::to_string(m.id) + "): " + what;
    // A material made in memory (tests) has no .mat and so no line to give.
    if (m.mat_file.empty()) throw DataError({"texture map", 0}, message);
    throw DataError({m.mat_file, m.texture_line ? m.texture_line : m.line}, message);
}

}  // namespace

int TextureMap::curve_at(double x, double y) const {
    // Invert the affine geotransform x = g0 + col g1 + row g2, y = g3 + col g4 + row g5.
    const auto& g = geotransform;
    double det = g[1] * g[5] - g[2] * g[4];
    double dx = x - g[0], dy = y - g[3];
    double col = (g[5] * dx - g[2] * dy) / det;
    double row = (-g[4] * dx + g[1] * dy) / det;
    if (!(col >= 0 && row >= 0 && col < static_cast<double>(columns) &&
          row < static_cast<double>(rows)))
        return -1;
    return curve[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                 static_cast<std::size_t>(col)];
}

std::shared_ptr<const TextureMap> read_texture_map(const std::string& path,
                                                   const MaterialOptics& m) {
    geo::gdal_init();
    geo::check_sidecars(path);
    // As GDALOpen(GA_ReadOnly) did: GDAL says why a file is not a raster it reads.
    const geo::GdalDataset ds = geo::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_VERBOSE_ERROR);
    if (!ds) texture_error(m, "cannot read TEXTURE_FILE " + path + ": " + geo::gdal_message());
    auto t = std::make_shared<TextureMap>();
    t->file = path;
    t->rows = ds->GetRasterYSize();
    t->columns = ds->GetRasterXSize();
    if (ds->GetGeoTransform(t->geotransform.data()) != CE_None)
        texture_error(m, "TEXTURE_FILE " + path +
                             " has no geotransform (it must place its cells in scene x, y)");
    const auto& g = t->geotransform;
    if (!(std::abs(g[1] * g[5] - g[2] * g[4]) > 0))
        texture_error(m, "TEXTURE_FILE " + path + ": singular geotransform");
    std::vector<double> values(static_cast<std::size_t>(t->rows * t->columns));
    if (ds->GetRasterCount() < 1 ||
        ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, static_cast<int>(t->columns),
                                       static_cast<int>(t->rows), values.data(),
                                       static_cast<int>(t->columns), static_cast<int>(t->rows),
                                       GDT_Float64, 0, 0) != CE_None)
        texture_error(m, "cannot read the cells of TEXTURE_FILE " + path);
    const auto curves = static_cast<double>(m.emissivity.size());
    t->curve.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        double v = values[i];
        if (!(v >= 0 && v < curves && v == std::floor(v)))
            texture_error(m, "TEXTURE_FILE " + path + ": cell (row " +
                                 std::to_string(i / static_cast<std::size_t>(t->columns)) +
                                 ", column " +
                                 std::to_string(i % static_cast<std::size_t>(t->columns)) +
                                 ") holds " + std::to_string(v) + ", not a curve number of its .ems (0 to " +
                                 std::to_string(m.emissivity.size() - 1) + ")");
        t->curve.push_back(static_cast<std::uint16_t>(v));
    }
    return t;
}

}  // namespace sigchain::radiometry
