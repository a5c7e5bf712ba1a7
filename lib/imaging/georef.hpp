// Where a sensor's pixels see the ground of a geo-placed scene, and the georeferencing
// of trace's outputs (cube(5), Georeferencing): a CRS and geotransform when the image
// grid lies on a map grid, else per-pixel geolocation arrays. Written for any Sensor,
// so the line scanner and pushbroom reuse it. The map side (CRS, scene ENU to map, the
// least-squares geotransform) is lib/geo/georef.*, which knows no sensor and no scene.
// Thread-safety: free functions; the scene and sensor are only read.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/report.hpp"
#include "geo/crs.hpp"
#include "geo/georef.hpp"
#include "image/image.hpp"
#include "imaging/sensor.hpp"
#include "scene/scene.hpp"

namespace sigchain::imaging {

// A scene placed on the Earth: its frame is east-north-up about the origin (the .snd's
// latitude and longitude at height 0 on WGS84), and its map CRS.
struct GeoPlacement {
    double latitude_deg = 0;
    double longitude_deg = 0;
    double meters_per_unit = 1;  // scene units -> m
    geo::Crs map_crs;
};

// Where a render lies on the Earth (cube(5), Georeferencing), from trace's --crs
// (`crs_option`): "none" gives none; "EPSG:N" or a WKT file that CRS; "" the CRS of
// the scene's DEM (scene::terrain_crs), else the UTM zone of the .snd's point
// `origin` (geo::utm_epsg), which `note` then names for -v. The frame's origin is
// `origin` at height 0; `snd_path` names the .snd in errors.
std::optional<GeoPlacement> geo_placement(const std::string& crs_option,
                                          const std::string& scene_path, const geo::LatLon& origin,
                                          double meters_per_unit, const std::string& snd_path,
                                          std::string& note);

// The largest misfit (pixels) between an image grid projected on the ground and an
// affine geotransform for which a geotransform is written: a hundredth of a pixel. A
// thousandth would refuse the Olinda scene, whose grid (10 km wide, 200 km from the UTM
// 25S central meridian) departs from any affine map by 0.0045 pixel through the change
// of UTM's scale factor across the image; a hundredth stays below the relief
// displacement of a frame render over terrain (0.02 pixel there), which no
// geotransform can hold, and ten times below the 0.1 pixel of a registration check.
inline constexpr double kGridAlignmentTolerancePx = 0.01;

// The geotransform of an image's rows from `row_begin` on (a part of a render): `gt`'s
// origin moved down `row_begin` rows.
inline geo::GeoTransform from_row(geo::GeoTransform gt, long row_begin) {
    gt[0] += static_cast<double>(row_begin) * gt[2];
    gt[3] += static_cast<double>(row_begin) * gt[5];
    return gt;
}

// The affine geotransform of rows [row_begin, row_end) of `sensor` (its row 0 = row_begin)
// onto the map CRS, fitted to a 17 x 17 lattice of image positions (corners included)
// whose rays are met with the scene's reference plane, z = 0 (height 0 above the
// origin). Empty when a lattice ray does not reach the plane (at or above the horizon).
// Terrain above or below the plane is displaced by its height times the ray's tangent of
// nadir angle (relief displacement, not part of the fit).
std::optional<geo::GeoTransformFit> fit_map_grid(const Sensor& sensor, const GeoPlacement& place,
                                                 long row_begin, long row_end);

// The scene point (scene units) seen along each pixel centre's ray, rows [row_begin,
// row_end) row-major: the first scene hit, else the ground plane at `plane_height`
// (scene units; none: no plane), else NaN in every coordinate.
std::vector<geo::Vec3> pixel_ground_points(const Sensor& sensor, const scene::Scene& scene,
                                           std::optional<double> plane_height, long row_begin,
                                           long row_end);

// What trace writes for rows [row_begin, row_end) of an image of `total_rows`: when the
// whole image's grid is within kGridAlignmentTolerancePx of an affine geotransform, the
// map CRS and that geotransform moved to row_begin (so the parts of a render agree);
// otherwise the ground points' WGS84 longitude and latitude written as geolocation
// arrays to `arrays_path` (kGeolocationNodata where a pixel sees no ground), named in
// the result with a lattice of them as ground control points. `note` receives one
// line for -v.
image::Georeference georeference_outputs(const Sensor& sensor, const scene::Scene& scene,
                                         const GeoPlacement& place,
                                         std::optional<double> plane_height, long row_begin,
                                         long row_end, long total_rows,
                                         const std::string& arrays_path, std::string& note);

// georeference_outputs as trace does it, its note to `reporter` (-v); when the map CRS
// was not named by the user (`crs_named` false: the DEM's or the UTM default), a view
// it cannot hold (a platform 1e9 m up) is written without georeferencing, with a
// warning, instead of failing.
image::Georeference georeference_render(const Sensor& sensor, const scene::Scene& scene,
                                        const GeoPlacement& place, bool crs_named,
                                        std::optional<double> plane_height, long row_begin,
                                        long row_end, long total_rows,
                                        const std::string& arrays_path, const Reporter& reporter);

}  // namespace sigchain::imaging
