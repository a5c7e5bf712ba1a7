// Tests for DEM terrain: vertex positions in the local east-north-up frame against the
// WGS84 radii of curvature (an independent first-order computation), a UTM raster
// through GeographicLib's own UTM (independent of GDAL/PROJ), nodata, winding, facet
// ids, land use, and the errors.
#include "core/numeric.hpp"
#include "scene/dem.hpp"

#include <cpl_conv.h>
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <unistd.h>

#include <GeographicLib/UTMUPS.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "scene/load.hpp"

using namespace sigchain;

namespace {

using sigchain::kRadPerDeg;
constexpr double kNodata = -9999;

// A small raster written with GDAL (GeoTIFF), band 1 = `values` (row-major).
void write_raster(const std::string& path, int rows, int cols, const std::array<double, 6>& gt,
                  int epsg, const std::vector<double>& values, bool with_nodata = false) {
    GDALAllRegister();
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
    ASSERT_NE(drv, nullptr);
    GDALDataset* ds = drv->Create(path.c_str(), cols, rows, 1, GDT_Float64, nullptr);
    ASSERT_NE(ds, nullptr);
    std::array<double, 6> g = gt;
    ds->SetGeoTransform(g.data());
    OGRSpatialReference srs;
    srs.importFromEPSG(epsg);
    ds->SetSpatialRef(&srs);
    GDALRasterBand* band = ds->GetRasterBand(1);
    if (with_nodata) band->SetNoDataValue(kNodata);
    std::vector<double> v = values;
    ASSERT_EQ(band->RasterIO(GF_Write, 0, 0, cols, rows, v.data(), cols, rows, GDT_Float64, 0, 0),
              CE_None);
    GDALClose(ds);
}

// A fresh directory for one test's rasters, removed with everything in it at the end.
struct TempDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("sigchain_dem_test_" + std::to_string(::getpid()) + "_" +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempDir() { std::filesystem::create_directories(path); }
    ~TempDir() { std::filesystem::remove_all(path); }
    std::string str() const { return path.string() + "/"; }
};

// WGS84 (NIMA TR8350.2): semi-major axis and flattening.
constexpr double kA = 6378137.0, kF = 1 / 298.257223563, kE2 = kF * (2 - kF);
// Meridional radius of curvature M and prime-vertical radius N at latitude phi.
double meridional_radius(double phi) {
    return kA * (1 - kE2) / std::pow(1 - kE2 * std::sin(phi) * std::sin(phi), 1.5);
}
double prime_vertical_radius(double phi) {
    return kA / std::sqrt(1 - kE2 * std::sin(phi) * std::sin(phi));
}

// First-order ENU of (lat, lon, h) about (lat0, lon0, h0): north = dlat (M(lat0) + h),
// east = dlon (N(lat0) + h) cos(lat0) (arcs at the point's height above the ellipsoid),
// up = dh minus the drop of the tangent plane d^2 / 2R.
std::array<double, 3> enu_first_order(double lat, double lon, double h, double lat0, double lon0,
                                      double h0) {
    double phi0 = lat0 * kRadPerDeg;
    double m = meridional_radius(phi0), n = prime_vertical_radius(phi0);
    double north = (lat - lat0) * kRadPerDeg * (m + h);
    double east = (lon - lon0) * kRadPerDeg * (n + h) * std::cos(phi0);
    double up = (h - h0) - (east * east + north * north) / (2 * std::sqrt(m * n));
    return {east, north, up};
}

const double kLat0 = 43.0, kLon0 = -77.6, kH0 = 100;

// 5 x 5 cells of 0.0002 deg about the origin (EPSG:4326), heights 100 + 2r + 3c + 0.5.
std::vector<double> heights() {
    std::vector<double> v(25);
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c) v[r * 5 + c] = 100 + 2 * r + 3 * c + 0.5;
    return v;
}
const std::array<double, 6> kGeoGt{-77.6005, 0.0002, 0, 43.0005, 0, -0.0002};

scene::DemSource source(const std::string& dem) {
    scene::DemSource s;
    s.dem_path = dem;
    s.material_id = 5;
    s.origin = {kLat0, kLon0, kH0};
    return s;
}

std::array<double, 3> vertex(const scene::MeshData& m, std::size_t i) {
    return {m.vertices[3 * i], m.vertices[3 * i + 1], m.vertices[3 * i + 2]};
}

std::string data_error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const DataError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(Dem, GeographicCellCentresLandWhereTheRadiiOfCurvaturePutThem) {
    TempDir tmp;
    std::string dir = tmp.str();
    auto h = heights();
    h[4] = kNodata;  // row 0, column 4: the second triangle of block (0, 3) goes
    write_raster(dir + "geo.tif", 5, 5, kGeoGt, 4326, h, true);
    scene::MeshData m =
        scene::read_dem_mesh(source(dir + "geo.tif"), scene::DegeneratePolicy::Error, nullptr);
    ASSERT_EQ(m.vertices.size(), 3u * 24);
    EXPECT_EQ(m.facets.size(), 31u);  // 16 blocks x 2, less the one with the nodata corner
    double worst = 0;
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c) {
            int i = r * 5 + c;
            if (i == 4) continue;
            auto v = vertex(m, static_cast<std::size_t>(i > 4 ? i - 1 : i));
            double lat = kGeoGt[3] + (r + 0.5) * kGeoGt[5], lon = kGeoGt[0] + (c + 0.5) * kGeoGt[1];
            auto ref = enu_first_order(lat, lon, h[i], kLat0, kLon0, kH0);
            // Offsets up to 33 m east and 44 m north: the first-order formulas neglect
            // terms of order d^2 / R (N sin(lat) dlat dlon = 2.5e-4 m, the parallels'
            // curvature, M and N varying across the grid) horizontally and d^3 / R^2
            // vertically; float storage of the coordinates adds 4e-6 m.
            EXPECT_NEAR(v[0], ref[0], 5e-4) << r << " " << c;
            EXPECT_NEAR(v[1], ref[1], 5e-4) << r << " " << c;
            EXPECT_NEAR(v[2], ref[2], 1e-4) << r << " " << c;
            for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(v[k] - ref[k]));
        }
    std::printf("geographic DEM: max |ENU - first order| %.3g m\n", worst);
    // Every triangle is wound upward; ids and origins name the block and the triangle.
    for (std::size_t t = 0; t < m.triangle_facet.size(); ++t) {
        auto a = vertex(m, m.triangles[3 * t]), b = vertex(m, m.triangles[3 * t + 1]),
             c = vertex(m, m.triangles[3 * t + 2]);
        EXPECT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0) << t;
    }
    EXPECT_EQ(m.origins[0].id, "1-1-1");
    EXPECT_EQ(m.origins[1].id, "1-1-2");
    EXPECT_EQ(m.origins[6].id, "1-4-1");  // block (0, 3): only its first triangle
    EXPECT_EQ(m.origins[7].id, "1-6-1");  // block (1, 0) is cell 6
    EXPECT_EQ(m.origins[7].description, "cell (row 2, column 1), triangle 1 (1-6-1)");
    EXPECT_EQ(m.origins[7].file, dir + "geo.tif");
    EXPECT_EQ(m.facets[7].material_id, 5);
}

TEST(Dem, UtmRasterAgreesWithGeographicLibUtm) {
    TempDir tmp;
    std::string dir = tmp.str();
    // UTM zone 18N (EPSG:32618): 4 x 3 cells of 10 m near the origin (43 N, 77.6 W).
    double x0 = 0, y0 = 0, gamma = 0, k = 0;
    int zone = 0;
    bool north = true;
    GeographicLib::UTMUPS::Forward(kLat0, kLon0, zone, north, x0, y0, gamma, k, 18);
    std::array<double, 6> gt{std::round(x0) - 20, 10, 0, std::round(y0) + 15, 0, -10};
    std::vector<double> h(12, kH0);
    write_raster(dir + "utm.tif", 3, 4, gt, 32618, h);
    scene::MeshData m =
        scene::read_dem_mesh(source(dir + "utm.tif"), scene::DegeneratePolicy::Error, nullptr);
    ASSERT_EQ(m.vertices.size(), 3u * 12);
    EXPECT_EQ(m.facets.size(), 12u);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) {
            double lat = 0, lon = 0;
            GeographicLib::UTMUPS::Reverse(18, true, gt[0] + (c + 0.5) * 10, gt[3] - (r + 0.5) * 10,
                                           lat, lon);
            auto ref = enu_first_order(lat, lon, kH0, kLat0, kLon0, kH0);
            auto v = vertex(m, static_cast<std::size_t>(r * 4 + c));
            // Offsets below 30 m: neglected second-order terms about 1e-4 m (as above);
            // PROJ's and GeographicLib's transverse Mercator agree far below that.
            EXPECT_NEAR(v[0], ref[0], 5e-4) << r << " " << c;
            EXPECT_NEAR(v[1], ref[1], 5e-4) << r << " " << c;
            EXPECT_NEAR(v[2], ref[2], 1e-4) << r << " " << c;
        }
}

TEST(Dem, FeetScaleElevationsAndOutput) {
    TempDir tmp;
    std::string dir = tmp.str();
    write_raster(dir + "geo_ft.tif", 5, 5, kGeoGt, 4326, heights());
    scene::DemSource s = source(dir + "geo_ft.tif");
    s.meters_per_unit = 0.3048;
    s.origin.height_m = 0;
    scene::MeshData m = scene::read_dem_mesh(s, scene::DegeneratePolicy::Error, nullptr);
    // Cell (2, 2) is at the origin's longitude and latitude: up = 110.5 ft, in ft.
    auto v = vertex(m, 12);
    EXPECT_NEAR(v[2], 110.5, 1e-4);
    // Cell (2, 4): 2 cells east, 116.5 ft high; tolerance as in the first test.
    auto ref = enu_first_order(43.0005 - 2.5 * 0.0002, -77.6005 + 4.5 * 0.0002, 116.5 * 0.3048,
                               kLat0, kLon0, 0);
    auto w = vertex(m, 14);
    EXPECT_NEAR(w[0], ref[0] / 0.3048, 5e-4 / 0.3048);
    EXPECT_NEAR(w[2], ref[2] / 0.3048, 1e-4 / 0.3048);
}

TEST(Dem, LandUseAssignsMaterialsPerBlock) {
    TempDir tmp;
    std::string dir = tmp.str();
    write_raster(dir + "lu_dem.tif", 5, 5, kGeoGt, 4326, heights());
    std::vector<double> classes(25);
    for (int i = 0; i < 25; ++i) classes[i] = (i % 5) < 2 ? 1 : 2;  // columns 0-1: class 1
    write_raster(dir + "lu.tif", 5, 5, kGeoGt, 4326, classes);
    scene::IdMap map = scene::parse_id_map("1 10\n2 20\n", "lu.map");
    scene::DemSource s = source(dir + "lu_dem.tif");
    s.material_id.reset();
    s.landuse_path = dir + "lu.tif";
    s.landuse_map = &map;
    scene::MeshData m = scene::read_dem_mesh(s, scene::DegeneratePolicy::Error, nullptr);
    ASSERT_EQ(m.facets.size(), 32u);
    for (std::size_t f = 0; f < m.facets.size(); ++f) {
        std::size_t block = f / 2, col = block % 4;  // the block's upper-left cell
        EXPECT_EQ(m.facets[f].material_id, col < 2 ? 10 : 20) << f;
    }
    // An unmapped class names the class, the cell and the map.
    scene::IdMap partial = scene::parse_id_map("1 10\n", "lu.map");
    s.landuse_map = &partial;
    EXPECT_EQ(
        data_error_of([&] { scene::read_dem_mesh(s, scene::DegeneratePolicy::Error, nullptr); }),
        dir + "lu.tif: cell (row 1, column 3): class 2 is not in the land-use map lu.map");
    // A class no triangle uses (the last column is no block's upper-left cell) need
    // not be mapped.
    for (int r = 0; r < 5; ++r) classes[r * 5 + 4] = 3;
    write_raster(dir + "lu_edge.tif", 5, 5, kGeoGt, 4326, classes);
    s.landuse_map = &map;
    s.landuse_path = dir + "lu_edge.tif";
    EXPECT_EQ(scene::read_dem_mesh(s, scene::DegeneratePolicy::Error, nullptr).facets.size(), 32u);
    // A land-use raster on another grid is refused.
    write_raster(dir + "lu_shifted.tif", 5, 5, {-77.6004, 0.0002, 0, 43.0005, 0, -0.0002}, 4326,
                 classes);
    s.landuse_map = &map;
    s.landuse_path = dir + "lu_shifted.tif";
    EXPECT_NE(data_error_of([&] {
                  scene::read_dem_mesh(s, scene::DegeneratePolicy::Error, nullptr);
              }).find("land use geotransform differs from the DEM's"),
              std::string::npos);
    write_raster(dir + "lu_small.tif", 4, 5, kGeoGt, 4326, std::vector<double>(20, 1));
    s.landuse_path = dir + "lu_small.tif";
    EXPECT_EQ(
        data_error_of([&] { scene::read_dem_mesh(s, scene::DegeneratePolicy::Error, nullptr); }),
        dir +
            "lu_small.tif: land use is 5 x 4 cells, the DEM 5 x 5; expected the same "
            "grid");
}

TEST(Dem, OdbObjectNeedsTheOriginAndPlacesTheTerrain) {
    TempDir tmp;
    std::string dir = tmp.str();
    write_raster(dir + "t.tif", 5, 5, kGeoGt, 4326, heights());
    std::ofstream(dir + "t.odb") << "OBJECT {\n    DEM_FILENAME = t.tif\n    MATERIAL_ID = 9\n"
                                    "    UNITS = m\n}\n";
    EXPECT_EQ(data_error_of([&] { scene::load_scene(dir + "t.odb", {}); }),
              dir +
                  "t.odb:1: a DEM object needs the scene's geodetic origin (the .snd latitude "
                  "and longitude) to be placed");
    scene::LoadOptions opt;
    opt.origin = scene::GeoOrigin{kLat0, kLon0, kH0};
    scene::LoadReport report;
    scene::Scene s = scene::load_scene(dir + "t.odb", opt, &report);
    EXPECT_EQ(report.facets, 32u);
    // Straight down onto the origin: cell (2, 2) is there at 110.5 m, 10.5 m above h0.
    auto hit = s.intersect({0.01, -0.01, 50}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->distance, 50 - 10.5, 0.01);  // slopes below 0.2 m/m over 1 cm
    EXPECT_EQ(s.attributes(*hit).material_id, 9);
    EXPECT_GT(hit->normal[2], 0.9);
    EXPECT_EQ(s.facet_key(*hit).substr(0, 6), "1.1/1-");
    std::string bad = dir + "nothing.tif";
    EXPECT_THROW(scene::read_dem_mesh(source(bad), scene::DegeneratePolicy::Error, nullptr),
                 IoError);
}

TEST(Dem, RastersWithoutCrsOrTooSmallAreRefused) {
    TempDir tmp;
    std::string dir = tmp.str();
    // An ESRI ASCII grid without its .prj: geo-transformed but no CRS.
    std::ofstream(dir + "nocrs.asc") << "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\n"
                                        "cellsize 1\n1 2 3\n4 5 6\n7 8 9\n";
    EXPECT_EQ(data_error_of([&] {
                  scene::read_dem_mesh(source(dir + "nocrs.asc"), scene::DegeneratePolicy::Error,
                                       nullptr);
              }),
              dir + "nocrs.asc: the DEM has no coordinate reference system");
    write_raster(dir + "thin.tif", 1, 5, kGeoGt, 4326, std::vector<double>(5, 0));
    EXPECT_EQ(data_error_of([&] {
                  scene::read_dem_mesh(source(dir + "thin.tif"), scene::DegeneratePolicy::Error,
                                       nullptr);
              }),
              dir + "thin.tif: a DEM needs at least 2 x 2 cells");
}

TEST(Dem, RasterGivenAsTheSceneIsTheOdbObjectWithoutItsPrefix) {
    TempDir tmp;
    std::string dir = tmp.str();
    write_raster(dir + "t.tif", 5, 5, kGeoGt, 4326, heights());
    std::ofstream(dir + "t.odb") << "OBJECT {\n    DEM_FILENAME = t.tif\n    MATERIAL_ID = 9\n"
                                    "    UNITS = m\n}\n";
    scene::LoadOptions opt;
    opt.origin = scene::GeoOrigin{kLat0, kLon0, kH0};
    const scene::Scene via_odb = scene::load_scene(dir + "t.odb", opt);
    // Without its materials, the raster is a usage error.
    EXPECT_THROW(scene::load_scene(dir + "t.tif", opt), UsageError);
    opt.input.material_id = 9;
    scene::LoadReport report;
    const scene::Scene lone = scene::load_scene(dir + "t.tif", opt, &report);
    EXPECT_EQ(report.facets, 32u);
    for (double x : {-5.0, 0.01, 7.5})
        for (double y : {-6.0, -0.01, 4.5}) {
            auto a = via_odb.intersect({x, y, 50}, {0, 0, -1});
            auto b = lone.intersect({x, y, 50}, {0, 0, -1});
            ASSERT_TRUE(a && b);
            EXPECT_EQ(a->distance, b->distance);  // the same floats, placed the same way
            EXPECT_EQ(lone.attributes(*b).material_id, 9);
            EXPECT_EQ("1.1/" + lone.facet_key(*b), via_odb.facet_key(*a));
        }
    // Land use as options: every class of the land use mapped to one id.
    write_raster(dir + "lu.tif", 5, 5, kGeoGt, 4326, std::vector<double>(25, 4));
    std::ofstream(dir + "lu.map") << "4 12\n";
    opt.input.material_id.reset();
    opt.input.landuse = dir + "lu.tif";
    EXPECT_THROW(scene::load_scene(dir + "t.tif", opt), UsageError);  // no --landuse-map
    opt.input.landuse_map = dir + "lu.map";
    const scene::Scene with_lu = scene::load_scene(dir + "t.tif", opt);
    auto hit = with_lu.intersect({0.01, -0.01, 50}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(with_lu.attributes(*hit).material_id, 12);
}

TEST(Dem, ALoneDemPlacesItselfAboutItsCentre) {
    TempDir tmp;
    std::string dir = tmp.str();
    // kGeoGt's 5 x 5 cells span 77.6005..77.5995 W, 42.9995..43.0005 N: centre 43 N 77.6 W.
    write_raster(dir + "geo.tif", 5, 5, kGeoGt, 4326, heights());
    const scene::GeoOrigin c = scene::dem_centre(dir + "geo.tif");
    EXPECT_NEAR(c.latitude_deg, kLat0, 1e-12);
    EXPECT_NEAR(c.longitude_east_deg, kLon0, 1e-12);
    EXPECT_EQ(c.height_m, 0);
    const std::optional<scene::GeoOrigin> lone = scene::lone_dem_origin(dir + "geo.tif");
    ASSERT_TRUE(lone);
    EXPECT_EQ(lone->latitude_deg, c.latitude_deg);
    EXPECT_EQ(lone->longitude_east_deg, c.longitude_east_deg);
    // Other scenes place nothing themselves (an .odb's DEM objects included).
    const std::string scenes = std::string(SIGCHAIN_TEST_DATA) + "/scene/";
    for (const char* other : {"plate.gdb", "flat.odb", "quad_tri.obj", "missing.tif"})
        EXPECT_FALSE(scene::lone_dem_origin(scenes + other)) << other;
    // Placed so, with geometry only (no materials), the centre cell is straight below.
    scene::LoadOptions opt;
    opt.origin = c;
    opt.geometry_only = true;
    const scene::Scene s = scene::load_scene(dir + "geo.tif", opt);
    // 30 cm east, 20 cm north of it the slopes (3 m a column of 16 m, 2 m a row of 22 m)
    // change the height by less than 0.1 m.
    const auto hit = s.intersect({0.3, 0.2, 1000}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(1000 - hit->distance, heights()[12], 0.1);  // 110.5 m at the origin
    EXPECT_EQ(s.attributes(*hit).material_id, 0);
}
