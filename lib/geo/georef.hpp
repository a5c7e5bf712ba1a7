// Georeferencing of an image whose pixels see a geo-placed scene: scene east-north-up
// metres to a map CRS (or WGS84 longitude/latitude), and the affine geotransform that
// maps image positions to map coordinates, with a measure of how well it does.
// Thread-safety: MapProjector is not thread-safe (one per thread, like OGR's
// transformations); the free functions are.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "geo/crs.hpp"
#include "geo/vec3.hpp"

namespace sigchain::geo {

// GDAL's geotransform: X = g0 + col * g1 + row * g2, Y = g3 + col * g4 + row * g5, with
// (col, row) = (0, 0) the top-left corner of the top-left pixel (CRS units).
using GeoTransform = std::array<double, 6>;

// The CRS named by `text`: "EPSG:N" (any code OGR knows) or a file holding a WKT (or
// PROJJSON) definition. Throws UsageError (unknown code, no such file) or DataError (a
// file that is not a CRS, naming it).
Crs crs_from_user(const std::string& text);
// The CRS of a GDAL raster (empty when it names none). Throws IoError when unreadable.
Crs raster_crs(const std::string& path);
// WGS84 longitude/latitude (EPSG:4326 with x = longitude), GDAL's geolocation SRS.
Crs wgs84_lon_lat();

// The map CRS a GIS user expects for a point with no other: the WGS84 UTM zone of
// GeographicLib's UTMUPS::StandardZone (Norway's and Svalbard's exceptions included),
// "EPSG:326NN" north of the equator and "EPSG:327NN" south, or WGS84 UPS north
// ("EPSG:32661", latitude >= 84 deg) and south ("EPSG:32761", below -80 deg). Throws
// DataError (at `where`) for a latitude outside [-90, 90].
std::string utm_epsg(double latitude_deg, double longitude_deg, const SourceLocation& where);

// Scene frame (east, north, up about a geodetic origin, metres) -> a map CRS.
class MapProjector {
public:
    // Throws DataError (naming `where`) when `map` cannot be reached from WGS84.
    MapProjector(const Crs& map, double origin_latitude_deg, double origin_longitude_deg,
                 double origin_height_m, const SourceLocation& where);
    ~MapProjector();
    MapProjector(const MapProjector&) = delete;
    MapProjector& operator=(const MapProjector&) = delete;

    // WGS84 longitude and latitude (deg) of a scene point (m), {lon, lat}.
    std::array<double, 2> lon_lat(const Vec3& enu_m) const;
    // WGS84 longitude, latitude (deg) and ellipsoidal height (m) of a scene point (m).
    std::array<double, 3> lon_lat_height(const Vec3& enu_m) const;
    // Map coordinates (x easting or longitude, y northing or latitude) of a scene point
    // (m); throws DataError when the point cannot be transformed.
    std::array<double, 2> map_xy(const Vec3& enu_m) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// One image position (pixel units, the Sensor convention) and its map coordinates.
struct GridTie {
    double column = 0, row = 0;
    double x = 0, y = 0;
};

// The least-squares affine geotransform through `ties` (at least 3, not collinear) and
// the largest distance between a tie's map position and the geotransform's, in pixels
// (map distance over the pixel size sqrt(|g1 g5 - g2 g4|)). Empty when the ties are
// too few or degenerate.
struct GeoTransformFit {
    GeoTransform geotransform{};
    double max_residual_px = 0;
};
std::optional<GeoTransformFit> fit_geotransform(const std::vector<GridTie>& ties);

}  // namespace sigchain::geo
