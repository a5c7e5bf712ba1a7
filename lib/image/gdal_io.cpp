// Reading rasters through GDAL: ENVI (.img + .hdr) and GeoTIFF, with per-band wavelengths
// (man cube(5)); the writer is gdal_write.cpp.
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal_priv.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/crs.hpp"
#include "geo/gdal_dataset.hpp"
#include "image/geolocation.hpp"
#include "image/image.hpp"
#include "image/internal.hpp"

namespace sigchain::image {

using geo::gdal_init;
using geo::gdal_message;

namespace {

// ENVI lists are "{a, b, c}"; a plain number is a one-element list.
std::vector<double> parse_number_list(const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (c == '{' || c == '}' || c == ',') c = ' ';
    std::istringstream in(s);
    in.imbue(std::locale::classic());
    std::vector<double> values;
    double v;
    while (in >> v) values.push_back(v);
    return values;
}

// Micrometres per unit of a wavelength unit name. Missing or unrecognised units
// ("Unknown" is common in ENVI headers) are inferred from the values: all at least 100
// means nanometres, otherwise micrometres (visible to thermal infrared: 0.3 to 15 um).
double um_per_unit(const std::string& units, const std::vector<double>& values) {
    const std::string u = ascii_lower(units);
    if (u == "micrometers" || u == "micrometer" || u == "microns" || u == "micron" || u == "um" ||
        u == "µm")
        return 1.0;
    if (u == "nanometers" || u == "nanometer" || u == "nm") return 1e-3;
    if (u == "millimeters" || u == "mm") return 1e3;
    for (double v : values)
        if (v < 100) return 1.0;
    return 1e-3;
}

// The ENVI data file for a .hdr path (GDAL opens the data file, not the header).
std::string envi_data_file(const std::string& path) {
    if (file_extension(path) != "hdr") return path;
    std::filesystem::path stem = std::filesystem::path(path).replace_extension();
    for (const char* ext : {".img", ".bsq", ".dat", ".IMG", ".BSQ", ".DAT", ""}) {
        std::filesystem::path candidate = stem;
        candidate += ext;
        if (std::filesystem::exists(candidate)) return candidate.string();
    }
    throw IoError(path + ": cannot open: no ENVI data file (.img, .bsq, .dat) beside the header");
}

// Errors name the image only: GDAL reads its metadata without line numbers.
void read_wavelengths(GDALDataset& ds, const std::string& path, Image& image) {
    std::vector<double> values;
    std::string units;
    if (const char* w = ds.GetMetadataItem("wavelength", "ENVI")) {
        values = parse_number_list(w);
        if (const char* u = ds.GetMetadataItem("wavelength_units", "ENVI")) units = u;
    } else {
        for (int b = 1; b <= ds.GetRasterCount(); ++b) {
            GDALRasterBand* band = ds.GetRasterBand(b);
            // `wavelength` with `wavelength_units` (cube(5)); WAVELENGTH_UM in older cubes.
            const char* w = band->GetMetadataItem("WAVELENGTH_UM");
            if (const char* w2 = band->GetMetadataItem("wavelength")) {
                w = w2;
                if (const char* u = band->GetMetadataItem("wavelength_units")) units = u;
            }
            if (!w) break;
            const std::vector<double> one = parse_number_list(w);
            if (one.size() != 1)
                throw DataError({path, 0}, "band " + std::to_string(b) +
                                               ": the wavelength is not a number: '" + w + "'");
            values.push_back(one[0]);
        }
        if (values.size() != static_cast<std::size_t>(ds.GetRasterCount())) values.clear();
    }
    if (values.empty()) return;
    if (values.size() != static_cast<std::size_t>(image.channels))
        throw DataError({path, 0}, "the wavelength list has " + std::to_string(values.size()) +
                                       " values for " + std::to_string(image.channels) + " bands");
    const double scale = um_per_unit(units, values);
    for (double& v : values) v *= scale;
    image.wavelength_um = values;
}

void read_units(GDALDataset& ds, Image& image) {
    if (const char* u = ds.GetMetadataItem("data_units", "ENVI"))
        image.units = u;
    else if (const char* u2 = ds.GetMetadataItem("UNITS"))
        image.units = u2;
    else if (ds.GetRasterCount() > 0)
        image.units = ds.GetRasterBand(1)->GetUnitType();
}

// The CRS and geotransform, the geolocation arrays' file (found as find_geolocation
// says) and the ground control points (cube(5), Georeferencing).
void read_georeference(GDALDataset& ds, Image& image, const std::string& path) {
    std::array<double, 6> gt{};
    const char* wkt = ds.GetProjectionRef();
    if (ds.GetGeoTransform(gt.data()) == CE_None && wkt && *wkt) {
        image.georef.geotransform = gt;
        image.georef.crs_wkt = wkt;
    }
    if (const char* x = ds.GetMetadataItem("X_DATASET", "GEOLOCATION"))
        image.georef.geolocation_path = find_geolocation(x, path);
    else if (const char* e = ds.GetMetadataItem("sigchain_geolocation", "ENVI"))
        image.georef.geolocation_path = find_geolocation(e, path);
    const GDAL_GCP* gcps = ds.GetGCPs();
    for (int i = 0; gcps && i < ds.GetGCPCount(); ++i)
        image.georef.gcps.push_back(
            {gcps[i].dfGCPPixel, gcps[i].dfGCPLine, gcps[i].dfGCPX, gcps[i].dfGCPY});
}

// An ENVI data file holds exactly what its header describes: header offset + rows x
// columns x bands samples. GDAL reads a short file's missing samples as zeros and ignores
// a long file's surplus; either means the pair is not what was written (a truncated copy,
// a header of another cube), so both are refused.
void check_envi_size(GDALDataset& ds, const std::string& path, const std::string& data_path) {
    GDALDriver* driver = ds.GetDriver();
    if (!driver || std::string(driver->GetDescription()) != "ENVI") return;
    long long offset = 0;
    if (const char* o = ds.GetMetadataItem("header_offset", "ENVI")) offset = std::atoll(o);
    const int bytes = GDALGetDataTypeSizeBytes(ds.GetRasterBand(1)->GetRasterDataType());
    const long long want = offset + static_cast<long long>(ds.GetRasterXSize()) *
                                        ds.GetRasterYSize() * ds.GetRasterCount() * bytes;
    std::error_code ec;
    const auto have = std::filesystem::file_size(data_path, ec);
    if (ec) throw IoError(data_path + ": cannot read its size: " + ec.message());
    if (static_cast<long long>(have) != want)
        throw DataError({path, 0}, (data_path == path ? "the file" : data_path) + " holds " +
                                       std::to_string(have) +
                                       " bytes, but its header describes " +
                                       std::to_string(want) + " (" +
                                       std::to_string(ds.GetRasterYSize()) + " rows x " +
                                       std::to_string(ds.GetRasterXSize()) + " columns x " +
                                       std::to_string(ds.GetRasterCount()) + " bands x " +
                                       std::to_string(bytes) + " bytes" +
                                       (offset ? " after a " + std::to_string(offset) +
                                                     "-byte offset" : std::string()) +
                                       "): " + (static_cast<long long>(have) < want
                                                    ? "truncated"
                                                    : "more data than the header describes"));
}

}  // namespace

namespace detail {

// Errors name the image only: a binary raster has no lines.
Image read_gdal(const std::string& path) {
    gdal_init();
    const std::string data_path = envi_data_file(path);
    geo::check_sidecars(data_path);
    const geo::GdalDataset ds = geo::open_dataset(data_path);
    if (!ds) throw DataError({path, 0}, "not a readable raster image: " + gdal_message());
    if (ds->GetRasterCount() < 1) throw DataError({path, 0}, "the image has no bands");
    check_envi_size(*ds, path, data_path);
    Image image(ds->GetRasterYSize(), ds->GetRasterXSize(), ds->GetRasterCount());
    for (int c = 0; c < image.channels; ++c) {
        GDALRasterBand* band = ds->GetRasterBand(c + 1);
        float* plane = image.data.data() + c * image.plane_size();
        if (band->RasterIO(GF_Read, 0, 0, static_cast<int>(image.columns),
                           static_cast<int>(image.rows), plane, static_cast<int>(image.columns),
                           static_cast<int>(image.rows), GDT_Float32, 0, 0, nullptr) != CE_None)
            throw IoError(path + ": read error: " + gdal_message());
        image.channel_names.emplace_back(band->GetDescription());
    }
    read_wavelengths(*ds, path, image);
    read_units(*ds, image);
    read_georeference(*ds, image, path);
    return image;
}

}  // namespace detail

std::string Provenance::item(const std::string& key) const {
    for (const auto& [k, v] : items)
        if (k == key) return v;
    return "";
}

namespace {

const std::string kItemPrefix = "sigchain_";

// The ENVI description "{sigchain VERSION: COMMAND}", as GDAL gives the item: the
// version and command (none when it is not sigchain's).
void read_envi_description(const std::string& value, Provenance& p) {
    const std::string head = "sigchain ";
    std::string d = value;
    while (!d.empty() && (d.front() == ' ' || d.front() == '\n' || d.front() == '{'))
        d.erase(0, 1);
    while (!d.empty() && (d.back() == ' ' || d.back() == '\n' || d.back() == '}')) d.pop_back();
    if (d.rfind(head, 0) != 0) return;
    const auto colon = d.find(": ");
    p.version = d.substr(head.size(),
                         colon == std::string::npos ? std::string::npos : colon - head.size());
    if (colon != std::string::npos) p.command = d.substr(colon + 2);
}

// "{a,b,c}": GDAL's band descriptions add the wavelength to each name.
void read_envi_band_names(const std::string& value, Provenance& p) {
    std::string list = value;
    if (!list.empty() && list.front() == '{') list.erase(0, 1);
    if (!list.empty() && list.back() == '}') list.pop_back();
    std::size_t from = 0;
    for (;;) {
        const auto comma = list.find(',', from);
        std::string name = list.substr(from, comma - from);
        while (!name.empty() && name.front() == ' ') name.erase(0, 1);
        p.band_names.push_back(name);
        if (comma == std::string::npos) break;
        from = comma + 1;
    }
}

// The items of a KEY=VALUE metadata list, the keys in lower case.
std::vector<std::pair<std::string, std::string>> metadata_items(char** kv) {
    std::vector<std::pair<std::string, std::string>> items;
    for (; *kv; ++kv) {
        const std::string item = *kv;
        const auto eq = item.find('=');
        if (eq == std::string::npos) continue;
        items.emplace_back(ascii_lower(item.substr(0, eq)), item.substr(eq + 1));
    }
    return items;
}

// The ENVI header's description, sensor type, band names and "sigchain KEY" items.
void read_envi_provenance(char** envi, Provenance& p) {
    for (const auto& [key, value] : metadata_items(envi)) {
        if (key == "description")
            read_envi_description(value, p);
        else if (key == "sensor_type")
            p.sensor_type = value;
        else if (key == "band_names")
            read_envi_band_names(value, p);
        else if (key.rfind(kItemPrefix, 0) == 0 && key != "sigchain_geolocation")
            p.items.emplace_back(key.substr(kItemPrefix.size()), value);
    }
}

// A GeoTIFF's SIGCHAIN_VERSION, SIGCHAIN_COMMAND and SIGCHAIN_KEY metadata.
void read_tiff_provenance(char** md, Provenance& p) {
    for (const auto& [key, value] : metadata_items(md)) {
        if (key == "sigchain_version")
            p.version = value;
        else if (key == "sigchain_command")
            p.command = value;
        else if (key.rfind(kItemPrefix, 0) == 0)
            p.items.emplace_back(key.substr(kItemPrefix.size()), value);
    }
}

}  // namespace

// ENVI: the header's description "sigchain VERSION: COMMAND" and its "sigchain KEY"
// items (GDAL's ENVI metadata domain, spaces as underscores); GeoTIFF: the dataset
// metadata SIGCHAIN_VERSION, SIGCHAIN_COMMAND and SIGCHAIN_KEY (cube(5), Provenance).
Provenance read_provenance(const std::string& path) {
    gdal_init();
    const std::string data_path = envi_data_file(path);
    geo::check_sidecars(data_path);
    const geo::GdalDataset ds = geo::open_dataset(data_path);
    if (!ds) throw DataError({path, 0}, "not a readable raster image: " + gdal_message());
    Provenance p;
    if (char** envi = ds->GetMetadata("ENVI"))
        read_envi_provenance(envi, p);
    else if (char** md = ds->GetMetadata())
        read_tiff_provenance(md, p);
    return p;
}

}  // namespace sigchain::image
