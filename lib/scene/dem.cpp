// DEM terrain: GDAL raster -> WGS84 (OGR) -> local east-north-up (GeographicLib).
#include "scene/dem.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>

#include "core/error.hpp"
#include "core/text.hpp"
#include "image/gdal.hpp"

namespace sigchain::scene {

namespace {

using image::gdal_init;
using image::gdal_message;

struct Raster {
    std::unique_ptr<GDALDataset> ds;
    int rows = 0, cols = 0;
    std::array<double, 6> gt{};
    std::vector<double> values;  // row-major, band 1
    std::optional<double> nodata;
};

Raster open_raster(const std::string& path, const char* what) {
    gdal_init();
    Raster r;
    r.ds.reset(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!r.ds) throw IoError(path + ": cannot open the " + what + " raster: " + gdal_message());
    if (r.ds->GetRasterCount() < 1) throw DataError({path, 0}, std::string(what) + " has no band");
    if (r.ds->GetGeoTransform(r.gt.data()) != CE_None)
        throw DataError({path, 0}, std::string(what) + " has no geotransform (not geo-referenced)");
    r.rows = r.ds->GetRasterYSize();
    r.cols = r.ds->GetRasterXSize();
    GDALRasterBand* band = r.ds->GetRasterBand(1);
    int has = 0;
    double nd = band->GetNoDataValue(&has);
    if (has) r.nodata = nd;
    r.values.resize(static_cast<std::size_t>(r.rows) * r.cols);
    if (band->RasterIO(GF_Read, 0, 0, r.cols, r.rows, r.values.data(), r.cols, r.rows, GDT_Float64,
                       0, 0) != CE_None)
        throw IoError(path + ": read error: " + gdal_message());
    return r;
}

bool valid(const Raster& r, double v) { return std::isfinite(v) && !(r.nodata && v == *r.nodata); }

// The land-use raster must lie on the DEM's grid: same size, same geotransform (to
// 1e-9 relative: both are read from files, so equal grids compare equal), same CRS.
void require_same_grid(const Raster& dem, const Raster& lu, const std::string& lu_path) {
    if (lu.rows != dem.rows || lu.cols != dem.cols)
        throw DataError({lu_path, 0}, "land use is " + std::to_string(lu.cols) + " x " +
                                          std::to_string(lu.rows) + " cells, the DEM " +
                                          std::to_string(dem.cols) + " x " +
                                          std::to_string(dem.rows) + "; expected the same grid");
    for (int i = 0; i < 6; ++i)
        if (std::abs(lu.gt[i] - dem.gt[i]) > 1e-9 * std::max(1.0, std::abs(dem.gt[i])))
            throw DataError({lu_path, 0},
                            "land use geotransform differs from the DEM's "
                            "(coefficient " +
                                std::to_string(i) + ": " + format_number(lu.gt[i]) + " vs " +
                                format_number(dem.gt[i]) + ")");
    const OGRSpatialReference* a = dem.ds->GetSpatialRef();
    const OGRSpatialReference* b = lu.ds->GetSpatialRef();
    if (a && b && !a->IsSame(b))
        throw DataError({lu_path, 0}, "land use CRS differs from the DEM's");
}

// Material ids of land-use classes, looked up as blocks use them (a class that no
// triangle uses, such as the land use under nodata terrain, need not be mapped).
class LandUse {
public:
    LandUse(const DemSource& s, const Raster& dem)
        : m_source(s), m_raster(open_raster(s.landuse_path, "land-use")) {
        require_same_grid(dem, m_raster, s.landuse_path);
    }

    // The material of cell i (row-major), by the map.
    long material(std::size_t i) {
        double v = m_raster.values[i];
        if (std::isfinite(v) && v == std::round(v)) {
            auto it = m_cache.find(static_cast<long>(v));
            if (it != m_cache.end()) return it->second;
        }
        std::string cell = "cell (row " + std::to_string(i / m_raster.cols + 1) + ", column " +
                           std::to_string(i % m_raster.cols + 1) + ")";
        if (!std::isfinite(v) || v != std::round(v))
            throw DataError({m_source.landuse_path, 0},
                            cell + ": class " + format_number(v) + " is not an integer");
        auto c = static_cast<long>(v);
        const IdMap::Entry* e = m_source.landuse_map->find(std::to_string(c));
        if (!e)
            throw DataError({m_source.landuse_path, 0}, cell + ": class " + std::to_string(c) +
                                                            " is not in the land-use map " +
                                                            m_source.landuse_map->file);
        return m_cache.emplace(c, e->id).first->second;
    }

private:
    const DemSource& m_source;
    Raster m_raster;
    std::unordered_map<long, long> m_cache;
};

std::unique_ptr<OGRCoordinateTransformation> to_wgs84(const Raster& r, const std::string& path) {
    const OGRSpatialReference* src = r.ds->GetSpatialRef();
    if (!src || src->IsEmpty())
        throw DataError({path, 0}, "the DEM has no coordinate reference system");
    OGRSpatialReference from(*src), wgs84;
    from.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = easting or longitude
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> t(
        OGRCreateCoordinateTransformation(&from, &wgs84));
    if (!t)
        throw DataError({path, 0}, "cannot transform the DEM's CRS to WGS84: " + gdal_message());
    return t;
}

// ENU vertices (object units) of the valid cells; index kNone for nodata cells.
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::vector<std::uint32_t> cell_vertices(const DemSource& s, const Raster& dem, MeshBuilder& b) {
    auto t = to_wgs84(dem, s.dem_path);
    GeographicLib::LocalCartesian enu(s.origin.latitude_deg, s.origin.longitude_east_deg,
                                      s.origin.height_m);
    std::vector<std::uint32_t> index(dem.values.size(), kNone);
    std::vector<double> x(dem.cols), y(dem.cols);
    std::vector<int> ok(dem.cols);
    for (int r = 0; r < dem.rows; ++r) {
        for (int c = 0; c < dem.cols; ++c) {  // cell centre (GDAL geotransform)
            x[c] = dem.gt[0] + (c + 0.5) * dem.gt[1] + (r + 0.5) * dem.gt[2];
            y[c] = dem.gt[3] + (c + 0.5) * dem.gt[4] + (r + 0.5) * dem.gt[5];
        }
        if (!t->Transform(dem.cols, x.data(), y.data(), nullptr, ok.data()))
            throw DataError({s.dem_path, 0}, "cannot transform row " + std::to_string(r + 1) +
                                                 " to WGS84: " + gdal_message());
        for (int c = 0; c < dem.cols; ++c) {
            std::size_t i = static_cast<std::size_t>(r) * dem.cols + c;
            if (!valid(dem, dem.values[i])) continue;
            if (!ok[c])
                throw DataError({s.dem_path, 0}, "cell (row " + std::to_string(r + 1) +
                                                     ", column " + std::to_string(c + 1) +
                                                     ") cannot be transformed to WGS84");
            double e = 0, n = 0, u = 0;
            enu.Forward(y[c], x[c], dem.values[i] * s.meters_per_unit, e, n, u);
            index[i] =
                b.add_vertex({e / s.meters_per_unit, n / s.meters_per_unit, u / s.meters_per_unit});
        }
    }
    return index;
}

}  // namespace

MeshData read_dem_mesh(const DemSource& s, DegeneratePolicy policy,
                       std::vector<std::string>* warnings) {
    Raster dem = open_raster(s.dem_path, "DEM");
    if (dem.rows < 2 || dem.cols < 2)
        throw DataError({s.dem_path, 0}, "a DEM needs at least 2 x 2 cells");
    std::optional<LandUse> lu;
    if (!s.landuse_path.empty()) lu.emplace(s, dem);
    MeshBuilder b(policy, warnings);
    std::vector<std::uint32_t> index = cell_vertices(s, dem, b);
    std::vector<std::uint32_t> tri(3);
    for (int r = 0; r + 1 < dem.rows; ++r)
        for (int c = 0; c + 1 < dem.cols; ++c) {
            std::size_t i = static_cast<std::size_t>(r) * dem.cols + c;
            std::uint32_t a = index[i], bb = index[i + 1], d = index[i + dem.cols],
                          e = index[i + dem.cols + 1];
            const std::array<std::array<std::uint32_t, 3>, 2> tris{{{a, d, e}, {a, e, bb}}};
            FacetAttributes attr;
            attr.material_id = s.material_id.value_or(0);
            for (int k = 0; k < 2; ++k) {
                if (tris[k][0] == kNone || tris[k][1] == kNone || tris[k][2] == kNone) continue;
                if (lu) attr.material_id = lu->material(i);
                tri.assign(tris[k].begin(), tris[k].end());
                if (!b.faces_up(tri)) std::swap(tri[1], tri[2]);
                std::string id = "1-" + std::to_string(i + 1) + "-" + std::to_string(k + 1);
                FacetOrigin o{s.dem_path, 0,
                              "cell (row " + std::to_string(r + 1) + ", column " +
                                  std::to_string(c + 1) + "), triangle " + std::to_string(k + 1) +
                                  " (" + id + ")",
                              id};
                b.add_facet(tri, attr, std::move(o));
            }
        }
    return b.take();
}

}  // namespace sigchain::scene
