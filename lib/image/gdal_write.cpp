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
#include "image/gdal_write.hpp"
#include "image/geolocation.hpp"
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

// The header lines GDAL 3.6's ENVI reader takes: a line of this many characters or
// more is an error there, and the items from it on are lost.
constexpr std::size_t kEnviLineLimit = 10000;

// ENVI's list form: "{a, b, c}", on the line "KEY = {...}" when it stays under
// kEnviLineLimit; else over several lines, 8 values to a line (a list of ~480
// wavelengths or more: a hyperspectral cube), which ENVI and GDAL read as one list.
std::string number_list(const std::string& key, const std::vector<double>& values) {
    std::string s = "{";
    for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + format_number(values[i]);
    s += "}";
    if (key.size() + 3 + s.size() < kEnviLineLimit) return s;
    std::string lines = "{";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) lines += i % 8 ? ", " : ",\n ";
        lines += format_number(values[i]);
    }
    return lines + "}";
}

// Errors name the output file only: they concern the image in memory, not a line.
void check_header(const std::string& path, const Image& image) {
    if (image.channels < 1 || image.rows < 1 || image.columns < 1)
        throw DataError({path, 0}, "cannot write an empty image");
    for (const auto* list : {&image.wavelength_um, &image.fwhm_um})
        if (!list->empty() && list->size() != static_cast<std::size_t>(image.channels))
            throw DataError({path, 0}, "the wavelength or FWHM list does not match the band count");
}

void check_image(const std::string& path, const Image& image) {
    check_header(path, image);
    if (image.data.size() != static_cast<std::size_t>(image.channels) * image.plane_size())
        throw DataError({path, 0}, "image data size does not match its dimensions");
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
        // GDAL's unit type is that of value * scale + offset (as CF's units of an
        // unpacked variable): with a scale, the scaled unit; the dataset's UNITS still
        // names the raw values.
        const bool scaled = static_cast<std::size_t>(c) < image.scale.size();
        if (scaled) {
            band->SetScale(image.scale[c]);
            band->SetOffset(image.offset[c]);
        }
        const std::string& unit = scaled ? image.scaled_units : image.units;
        if (!unit.empty()) band->SetUnitType(unit.c_str());
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
    if (!g.gcps.empty() && format == CubeFormat::Envi) {
        // GDAL's ENVI driver writes only 4 of a list of GCPs: the header's "geo points"
        // (ENVI's 1-based pixel, line, latitude, longitude), all of them, which it reads.
        std::string points = "{";
        for (std::size_t i = 0; i < g.gcps.size(); ++i) {
            const GroundControlPoint& p = g.gcps[i];
            char item[128];
            std::snprintf(item, sizeof item, "%s%.4f, %.4f, %.9f, %.9f", i ? ",\n " : "\n ",
                          p.pixel + 1, p.line + 1, p.latitude_deg, p.longitude_deg);
            points += item;
        }
        ds.SetMetadataItem("geo_points", (points + "}").c_str(), "ENVI");
    } else if (!g.gcps.empty()) {
        std::vector<GDAL_GCP> gcps(g.gcps.size());
        std::vector<std::string> ids(g.gcps.size());
        for (std::size_t i = 0; i < gcps.size(); ++i) {
            ids[i] = std::to_string(i + 1);
            gcps[i] = {const_cast<char*>(ids[i].c_str()), const_cast<char*>(""), g.gcps[i].pixel,
                       g.gcps[i].line, g.gcps[i].longitude_deg, g.gcps[i].latitude_deg, 0.0};
        }
        const geo::Crs wgs84 = geo::wgs84_lon_lat();
        if (ds.SetGCPs(static_cast<int>(gcps.size()), gcps.data(), wgs84.ogr()) != CE_None)
            throw IoError(path + ": cannot write the ground control points: " + gdal_message());
    }
    if (g.geolocation_path.empty()) return;
    // The file name alone: the arrays lie beside the image, where sigchain's readers
    // look; GDAL (3.6) opens the name from the working directory (run gdalwarp -geoloc
    // in the images' folder, or name them with SRC_GEOLOC_ARRAY, or use the GCPs). A
    // path would break when the pair is moved and make the bytes depend on the folder.
    const std::string arrays = std::filesystem::path(g.geolocation_path).filename().string();
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
        ds.SetMetadataItem("wavelength", number_list("wavelength", image.wavelength_um).c_str(), "ENVI");
        ds.SetMetadataItem("wavelength_units", "Micrometers", "ENVI");
    }
    if (all_finite(image.fwhm_um))
        ds.SetMetadataItem("fwhm", number_list("fwhm", image.fwhm_um).c_str(), "ENVI");
    // ENVI's display bands (1-based red, green, blue): the true-colour preview's, when
    // the image has three visible bands.
    if (all_finite(image.wavelength_um) && image.channels >= 3) {
        try {
            std::vector<double> rgb;
            for (int c : true_colour_bands(image, "")) rgb.push_back(c + 1);
            ds.SetMetadataItem("default_bands", number_list("default bands", rgb).c_str(), "ENVI");
        } catch (const DataError&) {
            // fewer than three visible bands: ENVI shows the first band
        }
    }
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
    std::unique_ptr<GdalOutput> out = detail::create_gdal(path, image, type, format, options);
    for (int c = 0; c < image.channels; ++c)
        out->write_band(c + 1, GDT_Float32, image.data.data() + c * image.plane_size());
    detail::commit_gdal(*out, image);
}

}  // namespace

void write_cube(const std::string& path, const Image& cube, CubeFormat format,
                const WriteOptions& options) {
    write_gdal(path, cube, GDT_Float32, format, options);
}

namespace detail {

std::unique_ptr<GdalOutput> create_gdal(const std::string& path, const Image& header,
                                        GDALDataType type, CubeFormat format,
                                        const WriteOptions& options) {
    gdal_init();
    check_header(path, header);
    const CPLStringList co = creation_options(path, format, options);
    std::string target = path;
    if (file_extension(path) == "hdr")
        target = std::filesystem::path(path).replace_extension(".img").string();
    auto out = std::make_unique<GdalOutput>(target, format == CubeFormat::GeoTiff ? "GTiff" : "ENVI",
                                            header.columns, header.rows, header.channels, type,
                                            co.List());
    set_metadata(out->dataset(), header, format, options);
    set_georeference(out->dataset(), header, format, path);
    return out;
}

void commit_gdal(GdalOutput& out, const Image& header) {
    if (!header.georef.arrays) {
        out.commit();
        return;
    }
    // The geolocation arrays and the image as one output: the arrays renamed first, the
    // image (and its ENVI header, which names them) last.
    std::unique_ptr<GdalOutput> arrays =
        stage_geolocation(header.georef.geolocation_path, *header.georef.arrays);
    std::vector<Move> image_moves = out.finish();
    std::vector<Move> moves = arrays->finish();
    moves.insert(moves.end(), image_moves.begin(), image_moves.end());
    commit_moves(moves);
}

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
