// Joining the parts of a render: provenance checks, then the rows copied into place.
#include "image/merge.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "core/output.hpp"
#include "image/geolocation.hpp"

namespace sigchain::image {

namespace {

bool parse_long(std::string_view text, long& value) {
    if (text.empty()) return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && value >= 0;
}

struct Part {
    std::string path;
    Provenance provenance;
    PartRows rows;
};

Part read_part(const std::string& path) {
    Part p{path, read_provenance(path), {}};
    const std::string rows = p.provenance.item("rows");
    const std::optional<PartRows> r = parse_part_rows(rows);
    if (!r)
        throw DataError({path, 0},
                        rows.empty() ? "not a part of a render: it records no rows (render parts "
                                       "with trace --tile K/N or --rows A:B; cube(5), Parts)"
                                     : "the part's rows '" + rows + "' are not A:B of R");
    p.rows = *r;
    return p;
}

// The same sigchain, the same inputs, the same options and the same image as `first`.
void check_same_render(const Part& first, const Part& p) {
    const Provenance &a = first.provenance, &b = p.provenance;
    const std::string other = " than " + first.path;
    if (a.version != b.version)
        throw DataError({p.path, 0}, "made by sigchain " + b.version + ", " + first.path +
                                         " by sigchain " + a.version);
    if (a.item("inputs") != b.item("inputs"))
        throw DataError({p.path, 0}, "made from other inputs" + other +
                                         " (the SHA-256 of the input files differ)");
    if (a.item("options") != b.item("options") || a.command.substr(0, a.command.find(' ')) !=
                                                      b.command.substr(0, b.command.find(' ')))
        throw DataError({p.path, 0}, "made with other options" + other + ": '" +
                                         b.item("options") + "' against '" + a.item("options") +
                                         "'");
    if (a.item("rows").empty() || p.rows.total != first.rows.total)
        throw DataError({p.path, 0}, "a part of an image of " + std::to_string(p.rows.total) +
                                         " rows, " + first.path + " of " +
                                         std::to_string(first.rows.total));
}

// Sorted by first row: no row twice, none left out.
void check_cover(std::vector<Part>& parts) {
    std::sort(parts.begin(), parts.end(),
              [](const Part& a, const Part& b) { return a.rows.begin < b.rows.begin; });
    long next = 0;
    const Part* previous = nullptr;
    for (const Part& p : parts) {
        if (p.rows.begin < next)
            throw DataError({p.path, 0}, "rows " + part_rows_text(p.rows) + " overlap rows " +
                                             part_rows_text(previous->rows) + " of " +
                                             previous->path);
        if (p.rows.begin > next)
            throw DataError({p.path, 0}, "rows " + std::to_string(next) + ":" +
                                             std::to_string(p.rows.begin) +
                                             " are missing: no part holds them");
        next = p.rows.end;
        previous = &p;
    }
    if (next < parts.back().rows.total)
        throw DataError({parts.back().path, 0},
                        "rows " + std::to_string(next) + ":" +
                            std::to_string(parts.back().rows.total) +
                            " are missing: no part holds them");
}

// The georeferencing of the whole from its parts' (cube(5), Georeferencing): the first
// part's CRS and geotransform (trace fits it to the whole image; each later part's is
// it moved to its first row), or the parts' geolocation arrays joined into
// `arrays_path` with their lattice of ground control points; none when no part has any.
Georeference join_georeference(const std::vector<Part>& parts, const std::vector<Georeference>& of,
                               long rows, long columns, const std::string& arrays_path) {
    const Georeference& first = of.front();
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const Georeference& g = of[i];
        const bool same_kind = g.geotransform.has_value() == first.geotransform.has_value() &&
                               g.geolocation_path.empty() == first.geolocation_path.empty();
        if (!same_kind || g.crs_wkt != first.crs_wkt)
            throw DataError({parts[i].path, 0}, "its georeferencing is not of the same kind or "
                                                "CRS as " + parts.front().path + "'s");
    }
    if (first.geolocation_path.empty()) {
        Georeference g = first;
        g.gcps.clear();
        return g;
    }
    GeolocationArrays whole;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        GeolocationArrays a = read_geolocation(of[i].geolocation_path);
        if (a.columns != columns || a.rows != parts[i].rows.end - parts[i].rows.begin)
            throw DataError({of[i].geolocation_path, 0},
                            "the geolocation arrays of " + parts[i].path +
                                " do not match its rows and columns");
        if (i == 0) {
            whole = a;
            whole.rows = rows;
            whole.x.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
            whole.y.resize(whole.x.size());
        }
        const auto at = static_cast<std::ptrdiff_t>(parts[i].rows.begin * columns);
        std::copy(a.x.begin(), a.x.end(), whole.x.begin() + at);
        std::copy(a.y.begin(), a.y.end(), whole.y.begin() + at);
    }
    Georeference g;
    g.geolocation_path = arrays_path;
    g.gcps = gcp_lattice(whole);
    g.arrays = std::make_shared<const GeolocationArrays>(std::move(whole));
    return g;
}

// Each part's planes into the whole image, band by band, and the whole's georeferencing
// (its geolocation arrays written to `arrays_path`).
Image join(const std::vector<Part>& parts, const std::string& arrays_path) {
    Image whole;
    std::vector<Georeference> georefs;
    for (const Part& p : parts) {
        Image part = read_image(p.path);
        georefs.push_back(part.georef);
        if (part.rows != p.rows.end - p.rows.begin)
            throw DataError({p.path, 0}, "records rows " + part_rows_text(p.rows) + " but holds " +
                                             std::to_string(part.rows) + " rows");
        if (whole.data.empty()) {
            whole = Image(p.rows.total, part.columns, part.channels);
            whole.wavelength_um = part.wavelength_um;
            // ENVI: the header's names (GDAL's band descriptions add the wavelength).
            const auto& names = p.provenance.band_names;
            whole.channel_names =
                names.size() == static_cast<std::size_t>(part.channels) ? names
                                                                        : part.channel_names;
            whole.units = part.units;
            whole.sensor_type = p.provenance.sensor_type;
        } else if (part.columns != whole.columns || part.channels != whole.channels ||
                   part.wavelength_um != whole.wavelength_um) {
            throw DataError({p.path, 0}, "its columns, bands or wavelengths differ from " +
                                             parts.front().path + "'s");
        }
        for (int c = 0; c < part.channels; ++c)
            std::copy_n(part.data.begin() + static_cast<std::ptrdiff_t>(c * part.plane_size()),
                        part.plane_size(),
                        whole.data.begin() + static_cast<std::ptrdiff_t>(
                                                 (c * whole.rows + p.rows.begin) * whole.columns));
    }
    whole.georef = join_georeference(parts, georefs, whole.rows, whole.columns, arrays_path);
    return whole;
}

std::string base_name(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::optional<PartRows> parse_part_rows(const std::string& text) {
    const auto colon = text.find(':'), of = text.find(" of ");
    PartRows r;
    if (colon == std::string::npos || of == std::string::npos || of < colon ||
        !parse_long(std::string_view(text).substr(0, colon), r.begin) ||
        !parse_long(std::string_view(text).substr(colon + 1, of - colon - 1), r.end) ||
        !parse_long(std::string_view(text).substr(of + 4), r.total) || r.end <= r.begin ||
        r.end > r.total)
        return std::nullopt;
    return r;
}

std::string part_rows_text(const PartRows& rows) {
    return std::to_string(rows.begin) + ":" + std::to_string(rows.end) + " of " +
           std::to_string(rows.total);
}

MergeReport run_merge(const MergeJob& job, const Reporter& reporter) {
    if (job.part_paths.empty()) throw UsageError("expected at least one PART");
    if (job.output_path.empty() || job.output_path == "-")
        throw UsageError("give the whole cube's name: -o CUBE");
    const CubeFormat format = cube_format_of(job.output_path);
    check_write_options(job.output_path, job.write_options);
    {
        std::filesystem::path img(job.output_path), hdr(job.output_path);
        if (format == CubeFormat::Envi) {
            img.replace_extension(".img");
            hdr.replace_extension(".hdr");
        }
        std::vector<std::string> inputs = job.part_paths;
        for (const std::string& p : job.part_paths)
            if (cube_format_of(p) == CubeFormat::Envi)
                inputs.push_back(std::filesystem::path(p).replace_extension(".hdr"));
        require_outputs_distinct({img.string(), hdr.string()}, inputs);
    }
    std::vector<Part> parts;
    for (const std::string& path : job.part_paths) parts.push_back(read_part(path));
    for (const Part& p : parts) check_same_render(parts.front(), p);
    check_cover(parts);
    Image whole = join(parts, geolocation_name(job.output_path));
    const Provenance& first = parts.front().provenance;
    WriteOptions options = job.write_options;
    const std::string tool = first.command.substr(0, first.command.find(' '));
    const std::string opts = first.item("options");
    options.command = tool + (opts.empty() ? "" : " " + opts) + " -o " + base_name(job.output_path);
    options.items.clear();
    reporter.info("merging " + std::to_string(parts.size()) + " part(s) into " +
                  std::to_string(whole.rows) + " rows, " + std::to_string(whole.columns) +
                  " columns, " + std::to_string(whole.channels) + " band(s)");
    write_cube(job.output_path, whole, format, options);
    return {whole.rows, whole.columns, whole.channels};
}

}  // namespace sigchain::image
