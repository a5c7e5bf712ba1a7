// DEM terrain: GDAL raster -> WGS84 (OGR) -> local east-north-up (GeographicLib).
#include "scene/dem.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <unordered_map>

#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/raster.hpp"

namespace sigchain::scene {

namespace {

using geo::GeoRaster;

// Memory a DEM cell takes once meshed: two triangles with their facet records (origin
// text, attributes, normal), the vertex and Embree's BVH; measured by
// bench/dem_memory.sh (1002 bytes: peak RSS against cells, 300² and 1200² DEMs).
constexpr double kBytesPerCell = 1000;

// The errors in this file name the raster without a line: a raster is binary. The cell
// concerned, where there is one, is named in the message instead.

// The land-use raster must lie on the DEM's grid: same size, same geotransform (to
// 1e-9 relative: both are read from files, so equal grids compare equal), same CRS.
void require_same_grid(const GeoRaster& dem, const GeoRaster& lu, const std::string& lu_path) {
    if (lu.rows != dem.rows || lu.columns != dem.columns)
        throw DataError({lu_path, 0}, "land use is " + std::to_string(lu.columns) + " x " +
                                          std::to_string(lu.rows) + " cells, the DEM " +
                                          std::to_string(dem.columns) + " x " +
                                          std::to_string(dem.rows) + "; expected the same grid");
    const auto& a = dem.geotransform;
    const auto& b = lu.geotransform;
    for (int i = 0; i < 6; ++i)
        if (std::abs(b[i] - a[i]) > 1e-9 * std::max(1.0, std::abs(a[i])))
            throw DataError({lu_path, 0},
                            "land use geotransform differs from the DEM's "
                            "(coefficient " +
                                std::to_string(i) + ": " + format_number(b[i]) + " vs " +
                                format_number(a[i]) + ")");
    if (!dem.crs.empty() && !lu.crs.empty() && !dem.crs.same_as(lu.crs))
        throw DataError({lu_path, 0}, "land use CRS differs from the DEM's");
}

// "cell (row R, column C)" of cell i (row-major, 1-based in the text).
std::string cell_name(std::size_t i, long columns) {
    return "cell (row " + std::to_string(i / columns + 1) + ", column " +
           std::to_string(i % columns + 1) + ")";
}

// Material ids of land-use classes, looked up as blocks use them (a class that no
// triangle uses, such as the land use under nodata terrain, need not be mapped).
class LandUse {
public:
    LandUse(const DemSource& s, const GeoRaster& dem)
        : m_source(s), m_raster(geo::read_geo_raster(s.landuse_path, geo::Bands::First)) {
        require_same_grid(dem, m_raster, s.landuse_path);
    }

    // The material of cell i (row-major), by the map.
    long material(std::size_t i) {
        double v = m_raster.values[i];
        if (std::isfinite(v) && v == std::round(v)) {
            auto it = m_cache.find(static_cast<long>(v));
            if (it != m_cache.end()) return it->second;
        }
        const std::string& path = m_source.landuse_path;
        if (!std::isfinite(v) || v != std::round(v))
            throw DataError({path, 0}, cell_name(i, m_raster.columns) + ": class " +
                                           format_number(v) + " is not an integer");
        auto c = static_cast<long>(v);
        const IdMap::Entry* e = m_source.landuse_map->find(std::to_string(c));
        if (!e)
            throw DataError({path, 0}, cell_name(i, m_raster.columns) + ": class " +
                                           std::to_string(c) + " is not in the land-use map " +
                                           m_source.landuse_map->file);
        return m_cache.emplace(c, e->id).first->second;
    }

private:
    const DemSource& m_source;
    GeoRaster m_raster;
    std::unordered_map<long, long> m_cache;
};

// ENU vertices (object units) of the valid cells; index kNone for nodata cells.
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::vector<std::uint32_t> cell_vertices(const DemSource& s, const GeoRaster& dem, MeshBuilder& b) {
    geo::require_crs(dem.crs, s.dem_path, "the DEM");
    const geo::Wgs84Transform to_wgs84(dem.crs, {s.dem_path, 0});
    const geo::LocalEnu enu(s.origin.latitude_deg, s.origin.longitude_east_deg, s.origin.height_m);
    const auto& gt = dem.geotransform;
    const int rows = static_cast<int>(dem.rows), cols = static_cast<int>(dem.columns);
    std::vector<std::uint32_t> index(dem.values.size(), kNone);
    std::vector<double> x(cols), y(cols);
    std::vector<int> ok(cols);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {  // cell centre (GDAL geotransform)
            x[c] = gt[0] + (c + 0.5) * gt[1] + (r + 0.5) * gt[2];
            y[c] = gt[3] + (c + 0.5) * gt[4] + (r + 0.5) * gt[5];
        }
        if (!to_wgs84.transform(cols, x.data(), y.data(), ok.data()))
            throw DataError({s.dem_path, 0}, "cannot transform row " + std::to_string(r + 1) +
                                                 " to WGS84: " + geo::gdal_message());
        for (int c = 0; c < cols; ++c) {
            std::size_t i = static_cast<std::size_t>(r) * cols + c;
            if (!dem.valid(dem.values[i])) continue;
            if (!ok[c])
                throw DataError({s.dem_path, 0},
                                cell_name(i, cols) + " cannot be transformed to WGS84");
            const geo::Vec3 p = enu.forward(y[c], x[c], dem.values[i] * s.meters_per_unit);
            index[i] = b.add_vertex(
                {p[0] / s.meters_per_unit, p[1] / s.meters_per_unit, p[2] / s.meters_per_unit});
        }
    }
    return index;
}

// An Esri ASCII grid (.asc) holds exactly rows x columns values after its header. GDAL
// reads the first rows x columns values, ignores any after them and reads missing ones
// as zero; either way the file is not the grid its header describes, so both are
// refused, at the line where the count goes wrong.
void check_ascii_grid(const std::string& path, long rows, long columns) {
    if (ascii_lower(std::filesystem::path(path).extension().string()) != ".asc") return;
    const TextInput in = TextInput::from_file(path);
    const std::size_t want = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
    std::size_t values = 0;
    const std::string& text = in.text();
    int line = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        const std::string_view row(text.data() + at, end - at);
        at = end + 1;
        ++line;
        for (std::string_view token : split_fields(row)) {
            if (values == 0 && std::isalpha(static_cast<unsigned char>(token[0]))) break;  // header
            double v;
            if (!try_parse_double(token, v))
                throw DataError({path, line}, "expected a height (a number), found '" +
                                                  std::string(token) + "'");
            if (++values > want)
                throw DataError({path, line}, "more values than the header's " +
                                                  std::to_string(columns) + " x " +
                                                  std::to_string(rows) + " (trailing data?)");
        }
    }
    if (values < want)
        throw DataError({path, line}, "the file ends after " + std::to_string(values) +
                                          " of the header's " + std::to_string(columns) + " x " +
                                          std::to_string(rows) + " values (a truncated file?)");
}

}  // namespace

MeshData read_dem_mesh(const DemSource& s, DegeneratePolicy policy,
                       std::vector<std::string>* warnings) {
    const GeoRaster dem = geo::read_geo_raster(s.dem_path, geo::Bands::First, kBytesPerCell,
                                               "as terrain (two triangles per cell)");
    if (dem.rows < 2 || dem.columns < 2)
        throw DataError({s.dem_path, 0}, "a DEM needs at least 2 x 2 cells");
    if (!(dem.geotransform[1] > 0) || dem.geotransform[5] == 0)
        throw DataError({s.dem_path, 0}, "the cell size is not positive (geotransform dx " +
                                             format_number(dem.geotransform[1]) + ", dy " +
                                             format_number(dem.geotransform[5]) + ")");
    check_ascii_grid(s.dem_path, dem.rows, dem.columns);
    std::optional<LandUse> lu;
    if (!s.landuse_path.empty()) lu.emplace(s, dem);
    MeshBuilder b(policy, warnings);
    std::vector<std::uint32_t> index = cell_vertices(s, dem, b);
    std::vector<std::uint32_t> tri(3);
    const long cols = dem.columns;
    for (long r = 0; r + 1 < dem.rows; ++r)
        for (long c = 0; c + 1 < cols; ++c) {
            std::size_t i = static_cast<std::size_t>(r) * cols + c;
            std::uint32_t a = index[i], bb = index[i + 1], d = index[i + cols],
                          e = index[i + cols + 1];
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

GeoOrigin dem_centre(const std::string& dem_path) {
    const GeoRaster dem = geo::read_geo_raster(dem_path, geo::Bands::First);
    geo::require_crs(dem.crs, dem_path, "the DEM");
    const auto& gt = dem.geotransform;
    const double c = 0.5 * static_cast<double>(dem.columns),
                 r = 0.5 * static_cast<double>(dem.rows);
    const geo::LatLon p =
        geo::Wgs84Transform(dem.crs, {dem_path, 0})
            .lat_lon(gt[0] + c * gt[1] + r * gt[2], gt[3] + c * gt[4] + r * gt[5]);
    return {p.latitude_deg, p.longitude_deg, 0.0};
}

}  // namespace sigchain::scene
