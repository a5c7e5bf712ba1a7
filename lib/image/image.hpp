// Raster images for sensorize and compare: radiance cubes (GDAL: ENVI, GeoTIFF) and
// digital-count or reference images (OpenImageIO: TIFF, PNG, JPEG; GDAL for the rest).
//
// Layout: planar float32, channel-major: channel c, row r, column x is
// data[(c * rows + r) * columns + x]. Row 0 is the top of the image.
// Thread-safety: plain value type.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sigchain::image {

// A ground control point: an image position (pixel units from the top-left corner of
// the top-left pixel, GDAL's convention) and its WGS84 longitude and latitude (deg).
struct GroundControlPoint {
    double pixel = 0, line = 0;
    double longitude_deg = 0, latitude_deg = 0;
};

struct GeolocationArrays;  // geolocation.hpp

// Where an image's pixels lie on the Earth (cube(5), Georeferencing); all empty for an
// image that is not geo-placed, which is then written exactly as before.
struct Georeference {
    std::string crs_wkt;  // the CRS of `geotransform` (WKT); "" for none
    // GDAL's geotransform (X = g0 + col g1 + row g2, Y = g3 + col g4 + row g5, from the
    // top-left corner of the top-left pixel), in crs_wkt's units.
    std::optional<std::array<double, 6>> geotransform;
    // The geolocation arrays' GeoTIFF (write_geolocation), named in the GDAL GEOLOCATION
    // metadata domain (ENVI: the header's `sigchain geolocation`); "" for none.
    // Written to this path; the image names the file alone (the arrays lie beside it).
    std::string geolocation_path;
    // The arrays to write at geolocation_path with the image, committed as one output
    // with it (a failed write leaves neither); null when they are on disk already.
    std::shared_ptr<const GeolocationArrays> arrays;
    // With geolocation arrays: a lattice of them as ground control points (at most
    // 17 x 17, pixel centres, WGS84 longitude and latitude), which place the image
    // wherever it is moved (GDAL GCPs: GeoTIFF tie points, ENVI `geo points`).
    std::vector<GroundControlPoint> gcps;
    bool empty() const { return !geotransform && geolocation_path.empty() && gcps.empty(); }
};

struct Image {
    long rows = 0;
    long columns = 0;
    int channels = 0;
    std::vector<float> data;                 // channels * rows * columns values
    std::vector<double> wavelength_um;       // per channel; empty when the file has none
    std::vector<double> fwhm_um;             // per channel band width (FWHM); may be empty
    std::vector<std::string> channel_names;  // per channel; may be empty
    std::string units;                       // "W cm-2 sr-1 um-1", "DC", or "" if unknown
    std::string sensor_type;                 // ENVI `sensor type`; "" writes none
    // Per channel, what turns a value back into a physical one: value * scale + offset
    // in `scaled_units` (GDAL's band scale, offset and unit type; counts carry their
    // band radiance so). Empty: none written.
    std::vector<double> scale, offset;
    std::string scaled_units;
    Georeference georef;                     // written by the GDAL writers (GeoTIFF, ENVI)

    Image() = default;
    Image(long rows, long columns, int channels, float fill = 0.0f);
    float& at(int c, long r, long x) {
        return data[(static_cast<std::size_t>(c) * rows + r) * columns + x];
    }
    float at(int c, long r, long x) const {
        return data[(static_cast<std::size_t>(c) * rows + r) * columns + x];
    }
    std::size_t plane_size() const { return static_cast<std::size_t>(rows) * columns; }
};

enum class CubeFormat { Envi, GeoTiff };

// How an output is written beyond its pixels (cube(5), PROVENANCE and CREATION OPTIONS).
struct WriteOptions {
    // GDAL GTiff creation options "KEY=VALUE" (sigchain's --co), after sigchain's own,
    // so that they override them; a non-empty list on a non-GeoTIFF output is a UsageError.
    std::vector<std::string> creation_options;
    // The command that made the output (cli::Context::command()): recorded with
    // sigchain's version; empty records the version alone.
    std::string command;
    // More provenance items, KEY (lowercase words joined by '_') and VALUE: ENVI header
    // items "sigchain KEY" (underscores as spaces), GeoTIFF dataset metadata SIGCHAIN_KEY
    // (upper case); a part of a whole records its rows, inputs and options (cube(5), Parts).
    // (A default member initializer: aggregate initializations that stop at `command`
    // stay warning-free.)
    std::vector<std::pair<std::string, std::string>> items{};
};

// What a cube records of how it was made (cube(5), Provenance and Parts), as read back.
struct Provenance {
    std::string version;  // sigchain's version ("" when the cube has none)
    std::string command;  // the recorded command ("" when none)
    std::string sensor_type;  // ENVI `sensor type` ("" when none)
    std::vector<std::string> band_names;  // ENVI `band names` as written (empty: none)
    // The items of WriteOptions::items, by KEY (lowercase, '_' between words).
    std::vector<std::pair<std::string, std::string>> items;
    // The value of item `key`, or "".
    std::string item(const std::string& key) const;
};
// Reads a cube's provenance through GDAL (ENVI or GeoTIFF). DataError naming `path`
// when it is not a readable raster.
Provenance read_provenance(const std::string& path);

// Throws UsageError when `options` carry creation options (--co) and `path` is not a
// GeoTIFF (.tif/.tiff) or a creation option is not KEY=VALUE: jobs call it before any work.
void check_write_options(const std::string& path, const WriteOptions& options);

// Reads any raster: ENVI (.hdr sidecar; the `wavelength` list and `wavelength units`
// are honoured, nanometres converted to micrometres) and GeoTIFF through GDAL; PNG,
// JPEG and TIFF through OpenImageIO. Integer pixels are returned as their count values
// (not normalised). Throws IoError (cannot open) or DataError (unusable content).
Image read_image(const std::string& path);

// Writes a float32 radiance cube through GDAL with per-band wavelength metadata,
// atomically (temporary name, then rename; for ENVI both .img and .hdr).
void write_cube(const std::string& path, const Image& cube, CubeFormat format,
                const WriteOptions& options = {});
// The cube format from a file name: .tif/.tiff -> GeoTiff, .img/.hdr/.bsq/.dat -> Envi.
CubeFormat cube_format_of(const std::string& path);

// Writes digital counts as 8- or 16-bit unsigned samples (12 bits are stored in 16-bit
// samples), one channel per band, atomically. Values must already be integers within the
// bit depth. .tif/.tiff: a GeoTIFF through GDAL, every band gray (PHOTOMETRIC=MINISBLACK,
// never alpha) with its name, wavelength and FWHM (cube(5)); uncompressed unless
// `options` say otherwise. PNG through OpenImageIO, and 8-bit plain-text Netpbm (.pgm for
// 1 channel, .ppm for 3), which tests diff as text.
void write_counts(const std::string& path, const Image& counts, int bits,
                  const WriteOptions& options = {});
// Writes float32 channels (unquantised band radiance, error maps) as a GeoTIFF through
// GDAL (as write_counts), atomically.
void write_float(const std::string& path, const Image& image, const WriteOptions& options = {});

// The channels of a true-colour preview, {red, green, blue}: of the bands whose centre
// wavelength lies in the visible 0.38-0.78 um, red the longest, blue the shortest,
// green the one between nearest 0.55 um. DataError naming `path` (the preview) when
// fewer than 3 (or none has a wavelength).
std::vector<int> true_colour_bands(const Image& image, const std::string& path);
// The channels of a preview: true_colour_bands' three when the image has them, else
// one band shown in grey, the shortest by centre wavelength (the first without
// wavelengths): a thermal or near-infrared sensor's.
std::vector<int> preview_bands(const Image& image);
// An 8-bit preview of preview_bands (sensorize(1), --preview): RGB, or one grey
// channel; each channel stretched linearly
// from the 2nd percentile (0) to the 98th (255), clipped and rounded: each band on
// its own, or with `common` one stretch for all (their values pooled), which
// keeps how bright one band is beside another. Where the percentiles coincide, the
// smallest and largest values; no spread at all gives mid-grey, a NaN pixel 0.
Image true_colour_preview(const Image& image, const std::string& path, bool common = false);

}  // namespace sigchain::image
