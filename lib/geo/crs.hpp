// Coordinate reference systems: a CRS read from a file, the transformation of its
// coordinates to WGS84 latitude and longitude (GDAL/OGR), and the local east-north-up
// frame about a geodetic origin (GeographicLib). The one path CRS -> WGS84 -> ENU that
// DEM terrain and land-cover rasters share.
#pragma once

#include <GeographicLib/LocalCartesian.hpp>
#include <cstddef>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "geo/vec3.hpp"

class OGRSpatialReference;
class OGRCoordinateTransformation;

namespace sigchain::geo {

// A coordinate reference system, or none (empty). Copies share one immutable OGR
// object. Thread-safety: const use from several threads is safe.
class Crs {
public:
    Crs() = default;
    // A copy of `srs` (nullptr or an empty reference gives an empty Crs).
    static Crs from_ogr(const OGRSpatialReference* srs);
    // Throws DataError (at `where`) when the WKT does not parse.
    static Crs from_wkt(const std::string& wkt, const SourceLocation& where);
    bool empty() const { return m_srs == nullptr; }
    // The CRS as WKT (GDAL's default WKT 1); "" when empty.
    std::string wkt() const;
    // The CRS as WKT2 (2019); "" when empty. WKT1 adds the TOWGS84 of a datum such as
    // SIRGAS 2000, which GDAL reads back as a BOUNDCRS that no longer names its EPSG code:
    // georeferenced outputs carry this form.
    std::string wkt2() const;
    // Whether both name the same CRS (OGR's IsSame); two empty ones are the same.
    bool same_as(const Crs& other) const;
    const OGRSpatialReference* ogr() const { return m_srs.get(); }

private:
    std::shared_ptr<const OGRSpatialReference> m_srs;
};

// Geodetic coordinates on WGS84 (deg, north and east positive).
struct LatLon {
    double latitude_deg = 0;
    double longitude_deg = 0;
};

// Transforms coordinates of one CRS to WGS84 latitude and longitude (OGR, traditional
// GIS axis order: x is easting or longitude, y northing or latitude). Not copyable;
// one per thread (OGR transformations are not thread-safe).
class Wgs84Transform {
public:
    // Throws DataError at `where` when `from` is empty or cannot be transformed.
    Wgs84Transform(const Crs& from, const SourceLocation& where);
    ~Wgs84Transform();
    Wgs84Transform(const Wgs84Transform&) = delete;
    Wgs84Transform& operator=(const Wgs84Transform&) = delete;

    // In place, n points: x becomes longitude and y latitude (deg); ok[i] is nonzero
    // where point i was transformed. False when the transformation failed as a whole.
    bool transform(std::size_t n, double* x, double* y, int* ok) const;
    // One point; throws DataError at the constructor's `where` when it fails.
    LatLon lat_lon(double x, double y) const;

private:
    std::unique_ptr<OGRCoordinateTransformation> m_transform;
    SourceLocation m_where;
};

// The local east-north-up frame (m) about a geodetic origin on WGS84 (GeographicLib's
// LocalCartesian): x east, y north, z up along the ellipsoid's normal at the origin.
class LocalEnu {
public:
    LocalEnu(double latitude_deg, double longitude_deg, double height_m)
        : m_enu(latitude_deg, longitude_deg, height_m) {}
    // (east, north, up) in m of a point at `height_m` above the ellipsoid.
    Vec3 forward(double latitude_deg, double longitude_deg, double height_m) const {
        Vec3 enu{0, 0, 0};
        m_enu.Forward(latitude_deg, longitude_deg, height_m, enu[0], enu[1], enu[2]);
        return enu;
    }

private:
    GeographicLib::LocalCartesian m_enu;
};

// GDAL set-up for every geo reader: registers the drivers once, keeps GDAL quiet (its
// errors become our messages through gdal_message()), writes no .aux.xml side files.
// Thread-safe; call before any other GDAL call. (lib/image keeps its own equivalent.)
void gdal_init();

// GDAL's last error message on this thread, or "unknown GDAL error".
std::string gdal_message();

// The side files GDAL reads with a raster (PATH's .prj, .hdr, .aux.xml, .tfw, .wld,
// .aux, .ovr and their upper-case forms, and PATH.aux.xml, PATH.ovr), checked before
// GDAL opens PATH, since GDAL reads them whole and unbounded: each that exists must
// be a regular file, and a text one (all but .ovr) at most kMaxSidecarBytes. Throws
// DataError naming the side file and the raster (sigchain(7), Text files).
inline constexpr long long kMaxSidecarBytes = 16LL << 20;  // 16 MiB
void check_sidecars(const std::string& path);

// Throws DataError when `crs` (read from the raster `path`) is empty: naming the
// raster's .prj and why GDAL could not read it when there is one (GDAL drops a bad
// .prj without a word, so the fault would be blamed on the raster), else
// "PATH: WHAT has no coordinate reference system".
void require_crs(const Crs& crs, const std::string& path, const std::string& what);

}  // namespace sigchain::geo
