// Tests for lib/geo/crs: a CRS from WKT and back, the transformation to WGS84 against
// GeographicLib's own UTM (independent of GDAL/PROJ), and the local east-north-up frame
// against the WGS84 radii of curvature.
#include "core/numeric.hpp"
#include "geo/crs.hpp"
#include "geo/georef.hpp"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <GeographicLib/UTMUPS.hpp>
#include <cmath>
#include <numbers>

using namespace sigchain::geo;

namespace {

using sigchain::kRadPerDeg;

Crs epsg(int code) {
    OGRSpatialReference srs;
    EXPECT_EQ(srs.importFromEPSG(code), OGRERR_NONE);
    return Crs::from_ogr(&srs);
}

// The DataError message of f(), or "" if it throws none.
template <class F>
std::string data_error_of(F f) {
    try {
        f();
    } catch (const sigchain::DataError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Crs, EmptyWktRoundTripAndSameness) {
    const Crs none;
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(none.wkt(), "");
    EXPECT_TRUE(Crs::from_ogr(nullptr).empty());
    const Crs utm = epsg(32725);
    EXPECT_FALSE(utm.empty());
    const Crs back = Crs::from_wkt(utm.wkt(), {"utm.wkt", 0});
    EXPECT_TRUE(back.same_as(utm));
    EXPECT_FALSE(back.same_as(epsg(4326)));
    EXPECT_FALSE(back.same_as(none));
    EXPECT_TRUE(none.same_as(Crs()));
    EXPECT_NE(data_error_of([] {
                  Crs::from_wkt("not a crs", {"x.wkt", 3});
              }).find("x.wkt:3: "),
              std::string::npos);
}

TEST(Wgs84Transform, UtmAgreesWithGeographicLibUtm) {
    // Olinda's UTM zone 25 south (EPSG:32725): GeographicLib's UTM (Karney 2011, Krueger
    // series, accurate to 5 nm) is an implementation independent of PROJ; both are
    // exact to far below 1e-9 deg (0.1 mm).
    const Wgs84Transform t(epsg(32725), {"dem.tif", 0});
    for (double e : {288776.25, 294000.0, 299000.0})
        for (double n : {9110000.0, 9120760.75}) {
            const LatLon p = t.lat_lon(e, n);
            double lat = 0, lon = 0;
            GeographicLib::UTMUPS::Reverse(25, false, e, n, lat, lon);
            EXPECT_NEAR(p.latitude_deg, lat, 1e-9);
            EXPECT_NEAR(p.longitude_deg, lon, 1e-9);
        }
    // Geographic input keeps longitude as x (traditional GIS order).
    const Wgs84Transform g(epsg(4326), {"g.tif", 0});
    double x[2] = {-34.9, -34.8}, y[2] = {-8.0, -7.9};
    int ok[2] = {0, 0};
    ASSERT_TRUE(g.transform(2, x, y, ok));
    EXPECT_TRUE(ok[0] && ok[1]);
    EXPECT_NEAR(x[0], -34.9, 1e-12);
    EXPECT_NEAR(y[1], -7.9, 1e-12);
}

TEST(UtmEpsg, ZonesOfKnownPlaces) {
    // Zones from the UTM definition (6 deg zones from 180 W; Norway's 32V and Svalbard's
    // 31X-37X exceptions; UPS north of 84 N and south of 80 S) and EPSG's WGS84 codes.
    const sigchain::SourceLocation at{"a.snd", 3};
    EXPECT_EQ(utm_epsg(-8.0, -34.9, at), "EPSG:32725");   // Olinda: 25 S
    EXPECT_EQ(utm_epsg(43.16, -77.61, at), "EPSG:32618");  // Rochester, NY: 18 N
    EXPECT_EQ(utm_epsg(0.0, 0.0, at), "EPSG:32631");       // the equator is north
    EXPECT_EQ(utm_epsg(60.39, 5.32, at), "EPSG:32632");    // Bergen: 32V, not 31
    EXPECT_EQ(utm_epsg(78.22, 15.65, at), "EPSG:32633");   // Longyearbyen: 33X
    EXPECT_EQ(utm_epsg(-17.8, 179.9, at), "EPSG:32760");   // Fiji: 60 S
    EXPECT_EQ(utm_epsg(85.0, 10.0, at), "EPSG:32661");     // UPS north
    EXPECT_EQ(utm_epsg(-80.5, 10.0, at), "EPSG:32761");    // UPS south
    EXPECT_EQ(data_error_of([&] { utm_epsg(91.0, 0.0, at); }).rfind("a.snd:3: ", 0), 0u);
}

TEST(Wgs84Transform, NeedsACrs) {
    EXPECT_EQ(data_error_of([] {
                  Wgs84Transform t(Crs(), {"dem.tif", 0});
              }),
              "dem.tif: no coordinate reference system");
}

TEST(LocalEnu, OffsetsAlongTheRadiiOfCurvature) {
    // WGS84 (NIMA TR8350.2): a = 6378137 m, f = 1/298.257223563. Meridional radius
    // M = a (1 - e^2) / (1 - e^2 sin^2 phi)^1.5, prime vertical N = a / sqrt(1 - e^2
    // sin^2 phi). Over 0.001 deg (110 m) the arcs differ from the first-order
    // offsets by far less than 1 mm (second order in the angle: ~1e-6 m).
    const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
    const double lat0 = -7.995376, lon0 = -34.871272, h0 = 12;
    const double s = std::sin(lat0 * kRadPerDeg);
    const double m = a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5);
    const double n = a / std::sqrt(1 - e2 * s * s);
    const LocalEnu enu(lat0, lon0, h0);
    const Vec3 o = enu.forward(lat0, lon0, h0);
    EXPECT_NEAR(o[0], 0, 1e-9);
    EXPECT_NEAR(o[1], 0, 1e-9);
    EXPECT_NEAR(o[2], 0, 1e-9);
    const Vec3 north = enu.forward(lat0 + 0.001, lon0, h0);
    EXPECT_NEAR(north[1], 0.001 * kRadPerDeg * (m + h0), 1e-3);
    EXPECT_NEAR(north[0], 0, 1e-6);
    const Vec3 east = enu.forward(lat0, lon0 + 0.001, h0);
    EXPECT_NEAR(east[0], 0.001 * kRadPerDeg * (n + h0) * std::cos(lat0 * kRadPerDeg), 1e-3);
    const Vec3 up = enu.forward(lat0, lon0, h0 + 100);
    EXPECT_NEAR(up[2], 100, 1e-9);
}
