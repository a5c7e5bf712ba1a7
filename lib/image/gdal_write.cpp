// Writing rasters through GDAL: radiance cubes (ENVI .img + .hdr, GeoTIFF) and the
// GeoTIFF counts and float images, with per-band names, wavelengths, FWHM and the
// provenance items of cube(5).
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "geo/crs.hpp"
#include "geo/georef.hpp"
#include "image/gdal_output.hpp"
#include "image/image.hpp"
#include "image/internal.hpp"
#include "sigchain/version.hpp"

namespace sigchain::image {

using geo::gdal_init;
using geo::gdal_message;

namespace {

std::string ascii_upper(std::string text) {
    for (char& c : text)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return text;
}

bool all_finite(const std::vector<double>& values) {
    return !values.empty() &&
           std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// ENVI's list form: "{a, b, c}".
std::string number_list(const std::vector<double>& values) {
    std::string s = "{";
    for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + format_number(values[i]);
    return s + "}";
}

// Errors name the output file only: they concern the image in memory, not a line.
void check_image(const std::string& path, const Image& image) {
    if (image.channels < 1 || image.rows < 1 || image.columns < 1)
        throw DataError({path, 0}, "cannot write an empty image");
    if (image.data.size() != static_cast<std::size_t>(image.channels) * image.plane_size())
        throw DataError({path, 0}, "image data size does not match its dimensions");
    for (const auto* list : {&image.wavelength_um, &image.fwhm_um})
        if (!list->empty() && list->size() != static_cast<std::size_t>(image.channels))
            throw DataError({path, 0}, "the wavelength or FWHM list does not match the band count");
}

// "sigchain X.Y.Z: COMMAND" (cube(5), PROVENANCE); braces would end an ENVI field.
std::string provenance(const WriteOptions& options) {
    std::string s = std::string("sigchain ") + kVersion;
    if (!options.command.empty()) s += ": " + options.command;
    for (char& c : s)
        if (c == '{')
            c = '(';
        else if (c == '}')
            c = ')';
    return s;
}

void set_band_metadata(GDALDataset& ds, const Image& image) {
    for (int c = 0; c < image.channels; ++c) {
        GDALRasterBand* band = ds.GetRasterBand(c + 1);
        if (static_cast<std::size_t>(c) < image.channel_names.size())
            band->SetDescription(image.channel_names[c].c_str());
        if (!image.units.empty()) band->SetUnitType(image.units.c_str());
        // A band whose wavelength or width is unknown (NaN) goes without the item.
        if (!image.wavelength_um.empty() && std::isfinite(image.wavelength_um[c])) {
            band->SetMetadataItem("wavelength", format_number(image.wavelength_um[c]).c_str());
            band->SetMetadataItem("wavelength_units", "Micrometers");
        }
        if (!image.fwhm_um.empty() && std::isfinite(image.fwhm_um[c]))
            band->SetMetadataItem("fwhm", format_number(image.fwhm_um[c]).c_str());
    }
}

// The CRS and geotransform, and the GEOLOCATION domain naming the arrays (cube(5),
// Georeferencing): nothing at all for an image that is not geo-placed.
void set_georeference(GDALDataset& ds, const Image& image, CubeFormat format,
                      const std::string& path) {
    const Georeference& g = image.georef;
    if (g.geotransform) {
        std::array<double, 6> gt = *g.geotransform;
        if (ds.SetGeoTransform(gt.data()) != CE_None ||
            ds.SetProjection(g.crs_wkt.c_str()) != CE_None)
            throw IoError(path + ": cannot write the georeferencing: " + gdal_message());
    }
    if (g.geolocation_path.empty()) return;
    // GDAL 3.6 opens X_DATASET relative to the working directory, not to this file:
    // the arrays are named by their absolute path.
    const std::string arrays = std::filesystem::absolute(g.geolocation_path).lexically_normal();
    if (format == CubeFormat::Envi) {
        ds.SetMetadataItem("sigchain_geolocation", arrays.c_str(), "ENVI");
        return;
    }
    CPLStringList items;
    items.SetNameValue("X_DATASET", arrays.c_str());
    items.SetNameValue("X_BAND", "1");
    items.SetNameValue("Y_DATASET", arrays.c_str());
    items.SetNameValue("Y_BAND", "2");
    items.SetNameValue("PIXEL_OFFSET", "0");
    items.SetNameValue("LINE_OFFSET", "0");
    items.SetNameValue("PIXEL_STEP", "1");
    items.SetNameValue("LINE_STEP", "1");
    items.SetNameValue("GEOREFERENCING_CONVENTION", "PIXEL_CENTER");  // a ray per pixel centre
    items.SetNameValue("SRS", geo::wgs84_lon_lat().wkt().c_str());
    ds.SetMetadata(items.List(), "GEOLOCATION");
}

void set_metadata(GDALDataset& ds, const Image& image, CubeFormat format,
                  const WriteOptions& options) {
    set_band_metadata(ds, image);
    if (format == CubeFormat::GeoTiff) {
        if (!image.units.empty()) ds.SetMetadataItem("UNITS", image.units.c_str());
        ds.SetMetadataItem("SIGCHAIN_VERSION", kVersion);
        if (!options.command.empty())
            ds.SetMetadataItem("SIGCHAIN_COMMAND", options.command.c_str());
        for (const auto& [key, value] : options.items)
            ds.SetMetadataItem(("SIGCHAIN_" + ascii_upper(key)).c_str(), value.c_str());
        return;
    }
    // GDAL writes the dataset description (by default the temporary file name) as the
    // header's description: the provenance keeps reruns identical.
    ds.SetDescription(provenance(options).c_str());
    if (all_finite(image.wavelength_um)) {
        ds.SetMetadataItem("wavelength", number_list(image.wavelength_um).c_str(), "ENVI");
        ds.SetMetadataItem("wavelength_units", "Micrometers", "ENVI");
    }
    if (all_finite(image.fwhm_um))
        ds.SetMetadataItem("fwhm", number_list(image.fwhm_um).c_str(), "ENVI");
    if (!image.units.empty()) ds.SetMetadataItem("data_units", image.units.c_str(), "ENVI");
    if (!image.sensor_type.empty())
        ds.SetMetadataItem("sensor_type", image.sensor_type.c_str(), "ENVI");
    for (const auto& [key, value] : options.items) {
        std::string v = value;  // braces would end the ENVI field, as in provenance()
        std::replace(v.begin(), v.end(), '{', '(');
        std::replace(v.begin(), v.end(), '}', ')');
        ds.SetMetadataItem(("sigchain_" + key).c_str(), v.c_str(), "ENVI");
    }
}

// sigchain's creation options, then the user's (--co), which override them.
CPLStringList creation_options(const std::string& path, CubeFormat format,
                               const WriteOptions& options) {
    CPLStringList list;
    list.SetNameValue("INTERLEAVE", format == CubeFormat::Envi ? "BSQ" : "BAND");
    if (format == CubeFormat::GeoTiff) list.SetNameValue("PHOTOMETRIC", "MINISBLACK");
    if (format != CubeFormat::GeoTiff && !options.creation_options.empty())
        throw UsageError(path + ": --co applies to GeoTIFF (.tif) outputs only");
    check_write_options(path, options);
    for (const std::string& kv : options.creation_options) {
        const auto eq = kv.find('=');
        list.SetNameValue(kv.substr(0, eq).c_str(), kv.substr(eq + 1).c_str());
    }
    return list;
}

// Writes `image` with GDAL as `type` samples, atomically (cube(5)).
void write_gdal(const std::string& path, const Image& image, GDALDataType type, CubeFormat format,
                const WriteOptions& options) {
    gdal_init();
    check_image(path, image);
    const CPLStringList co = creation_options(path, format, options);
    std::string target = path;
    if (file_extension(path) == "hdr")
        target = std::filesystem::path(path).replace_extension(".img").string();
    GdalOutput out(target, format == CubeFormat::GeoTiff ? "GTiff" : "ENVI", image.columns,
                   image.rows, image.channels, type, co.List());
    set_metadata(out.dataset(), image, format, options);
    set_georeference(out.dataset(), image, format, path);
    for (int c = 0; c < image.channels; ++c)
        out.write_band(c + 1, GDT_Float32, image.data.data() + c * image.plane_size());
    out.commit();
}

}  // namespace

void write_cube(const std::string& path, const Image& cube, CubeFormat format,
                const WriteOptions& options) {
    write_gdal(path, cube, GDT_Float32, format, options);
}

std::string geolocation_name(const std::string& output_path) {
    return std::filesystem::path(output_path).replace_extension(".geoloc.tif").string();
}

void write_geolocation(const std::string& path, long rows, long columns,
                       const std::vector<double>& x, const std::vector<double>& y,
                       const std::string& srs_wkt, double nodata) {
    gdal_init();
    const std::size_t n = static_cast<std::size_t>(rows) * columns;
    if (rows < 1 || columns < 1 || x.size() != n || y.size() != n)
        throw DataError({path, 0}, "geolocation arrays do not match the image's size");
    CPLStringList co;
    co.SetNameValue("INTERLEAVE", "BAND");
    GdalOutput out(path, "GTiff", columns, rows, 2, GDT_Float64, co.List());
    // The arrays' own SRS: GDAL's SRC_GEOLOC_ARRAY transformer option reads it.
    out.dataset().SetProjection(srs_wkt.c_str());
    const std::vector<double>* planes[2] = {&x, &y};
    const char* names[2] = {"x (longitude)", "y (latitude)"};
    for (int b = 0; b < 2; ++b) {
        GDALRasterBand* band = out.dataset().GetRasterBand(b + 1);
        band->SetDescription(names[b]);
        band->SetNoDataValue(nodata);
        out.write_band(b + 1, GDT_Float64, planes[b]->data());
    }
    out.commit();
}

void copy_geolocation(const std::string& from, const std::string& path) {
    gdal_init();
    std::unique_ptr<GDALDataset> src(static_cast<GDALDataset*>(
        GDALOpenEx(from.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!src || src->GetRasterCount() != 2)
        throw DataError({from, 0}, "not a geolocation array file (2 bands): " + gdal_message());
    const long rows = src->GetRasterYSize(), columns = src->GetRasterXSize();
    const std::size_t n = static_cast<std::size_t>(rows) * columns;
    std::vector<double> planes[2] = {std::vector<double>(n), std::vector<double>(n)};
    for (int b = 0; b < 2; ++b)
        if (src->GetRasterBand(b + 1)->RasterIO(GF_Read, 0, 0, static_cast<int>(columns),
                                                static_cast<int>(rows), planes[b].data(),
                                                static_cast<int>(columns), static_cast<int>(rows),
                                                GDT_Float64, 0, 0, nullptr) != CE_None)
            throw IoError(from + ": read error: " + gdal_message());
    int has_nodata = 0;
    const double nodata = src->GetRasterBand(1)->GetNoDataValue(&has_nodata);
    const char* wkt = src->GetProjectionRef();
    write_geolocation(path, rows, columns, planes[0], planes[1], wkt ? wkt : "",
                      has_nodata ? nodata : kGeolocationNodata);
}

namespace detail {

void validate_gtiff_options(const std::string& path, const std::vector<std::string>& options) {
    gdal_init();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    if (!driver) throw IoError(path + ": GDAL has no GTiff driver");
    CPLStringList list;
    for (const std::string& kv : options) {
        const auto eq = kv.find('=');
        list.SetNameValue(kv.substr(0, eq).c_str(), kv.substr(eq + 1).c_str());
    }
    CPLErrorReset();
    if (!GDALValidateCreationOptions(driver, list.List()))
        throw UsageError(path + ": invalid creation option: " + gdal_message());
}

void write_gtiff(const std::string& path, const Image& image, int bits,
                 const WriteOptions& options) {
    const GDALDataType type = bits == 8 ? GDT_Byte : bits <= 16 ? GDT_UInt16 : GDT_Float32;
    write_gdal(path, image, type, CubeFormat::GeoTiff, options);
}

}  // namespace detail
}  // namespace sigchain::image
