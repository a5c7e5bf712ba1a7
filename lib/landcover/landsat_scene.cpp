// The preparation and scoring steps of the real Landsat validation scenes.
#include "landcover/landsat_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "compare/compare.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "geo/raster.hpp"
#include "image/image.hpp"
#include "image/layers.hpp"
#include "io/cpt.hpp"
#include "landcover/fit.hpp"
#include "landcover/raster.hpp"
#include "landcover/score.hpp"
#include "landcover/spectra.hpp"

namespace sigchain::landcover {

namespace {

std::string fixed(double v, int decimals) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
    return b;
}

std::vector<geo::GeoRaster> read_all(const std::vector<std::string>& paths) {
    std::vector<geo::GeoRaster> out;
    for (const auto& p : paths) {
        out.push_back(geo::read_geo_raster(p));
        geo::require_north_up_with_crs(out.back(), p);
    }
    return out;
}

std::vector<const geo::GeoRaster*> pointers(const std::vector<geo::GeoRaster>& rasters) {
    std::vector<const geo::GeoRaster*> out;
    for (const auto& r : rasters) out.push_back(&r);
    return out;
}

std::vector<int> integers(const geo::GeoRaster& r) {
    std::vector<int> out(static_cast<std::size_t>(r.rows) * r.columns);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<int>(std::lround(r.values[i]));
    return out;
}

// Union of masks (non-zero anywhere), each the size of `rows` x `columns`.
std::vector<int> union_of(const std::vector<std::string>& paths, long rows, long columns) {
    std::vector<int> out(static_cast<std::size_t>(rows) * columns, 0);
    for (const auto& p : paths) {
        const auto m = geo::read_geo_raster(p, geo::Bands::First);
        if (m.rows != rows || m.columns != columns)
            throw DataError({p, 0}, "the mask is " + std::to_string(m.rows) + " x " +
                                        std::to_string(m.columns) + ", the image " +
                                        std::to_string(rows) + " x " + std::to_string(columns));
        for (std::size_t i = 0; i < out.size(); ++i)
            if (m.values[i] != 0) out[i] = 1;
    }
    return out;
}

void report_fractions(const std::vector<int>& values, const std::map<int, std::string>& names,
                      std::ostream& report) {
    std::map<int, long> count;
    for (int v : values) ++count[v];
    for (const auto& [k, n] : count) {
        const auto it = names.find(k);
        report << k << " " << (it == names.end() ? "-" : it->second) << " "
               << fixed(double(n) / values.size(), 4) << "\n";
    }
}

// Values of band b at the points of class `cls` (names CLASS_NN) of one image.
std::vector<double> class_values(const image::Image& img, int b, const io::Cpt& cpt,
                                 const std::string& path, const std::string& cls,
                                 bool synthetic) {
    std::vector<double> v;
    for (const auto& p : cpt.points) {
        if (p.name.substr(0, p.name.rfind('_')) != cls) continue;
        v.push_back(compare::control_point_value(
            img, b, synthetic ? p.synthetic_row : p.reference_row,
            synthetic ? p.synthetic_column : p.reference_column, p.radius_px, {path, p.line},
            synthetic ? "synthetic image" : "reference image"));
    }
    return v;
}

}  // namespace

void classify_step(const std::string& rules_path, const std::vector<std::string>& images,
                   const std::string& mask_path, const std::string& out_path,
                   std::ostream& report) {
    const auto rules = read_class_rules(rules_path);
    const auto rasters = read_all(images);
    auto classes = classify(rules, pointers(rasters));
    const auto& first = rasters.front();
    // Pixels no rule classifies stay 0; masked pixels take their neighbours' class (-1
    // marks the first while the second are filled: it neither votes nor is filled).
    long hidden = 0;
    for (int& k : classes)
        if (k == 0) k = -1;
    if (!mask_path.empty()) {
        const auto mask = union_of({mask_path}, first.rows, first.columns);
        for (std::size_t i = 0; i < classes.size(); ++i)
            if (mask[i]) classes[i] = 0, ++hidden;
    }
    std::map<int, std::string> names{{-1, "unclassified"}, {0, "masked"}};
    for (const auto& r : rules.rules) names[r.id] = r.name;
    report << "# class name fraction (before filling " << hidden << " masked pixels)\n";
    report_fractions(classes, names, report);
    fill_unclassified(classes, first.rows, first.columns);
    for (int& k : classes)
        if (k < 0) k = 0;
    write_class_raster(out_path, first.rows, first.columns, classes, first.geotransform,
                       first.crs);
}

void mask_step(const CloudMaskRequest& request, const std::vector<std::string>& images,
               const std::string& out_path, std::ostream& report) {
    const auto rasters = read_all(images);
    const auto mask = cloud_mask(pointers(rasters), request);
    const auto& first = rasters.front();
    report << "# mask value fraction\n";
    report_fractions(mask, {{kMaskClear, "clear"}, {kMaskCloud, "cloud"}, {kMaskShadow, "shadow"}},
                     report);
    write_class_raster(out_path, first.rows, first.columns, mask, first.geotransform, first.crs);
}

void terrain_step(const std::string& dem_path, const std::string& classes_path,
                  const std::string& outdir, std::ostream& report) {
    const auto dem = geo::read_geo_raster(dem_path, geo::Bands::First);
    geo::require_north_up_with_crs(dem, dem_path);
    const auto cls = geo::read_geo_raster(classes_path, geo::Bands::First);
    geo::require_north_up_with_crs(cls, classes_path);
    const long rows = cls.rows, columns = cls.columns;
    for (int k = 0; k < 6; ++k)
        if (dem.rows != rows || dem.columns != columns ||
            std::abs(dem.geotransform[k] - cls.geotransform[k]) > 1e-3 * std::abs(cls.geotransform[1]))
            throw DataError({dem_path, 0}, "the DEM is not on the class map's grid (" +
                                               classes_path + ")");
    const long cr = rows + 1, cc = columns + 1;
    std::vector<double> corners(static_cast<std::size_t>(cr) * cc, 0);
    for (long r = 0; r < cr; ++r)
        for (long c = 0; c < cc; ++c) {
            double sum = 0;
            int n = 0;
            for (long y = r - 1; y <= r; ++y)
                for (long x = c - 1; x <= c; ++x)
                    if (y >= 0 && x >= 0 && y < rows && x < columns && dem.valid(dem.at(0, y, x)))
                        sum += dem.at(0, y, x), ++n;
            if (n == 0) throw DataError({dem_path, 0}, "no DEM value around a pixel corner");
            corners[r * cc + c] = sum / n;
        }
    std::vector<int> landuse(corners.size(), 0);
    for (long r = 0; r < cr; ++r)
        for (long c = 0; c < cc; ++c)
            landuse[r * cc + c] = static_cast<int>(
                std::lround(cls.at(0, std::min(r, rows - 1), std::min(c, columns - 1))));
    auto gt = cls.geotransform;  // corner (0, 0) is the centre of the new grid's cell (0, 0)
    gt[0] -= gt[1] / 2;
    gt[3] -= gt[5] / 2;
    image::Layers terrain;
    terrain.rows = cr, terrain.columns = cc;
    terrain.names = {"height (m)"};
    terrain.planes = {corners};
    terrain.srs_wkt = cls.crs.wkt();
    terrain.geotransform = gt;
    image::write_layers(outdir + "/terrain.tif", terrain);
    write_class_raster(outdir + "/landuse.tif", cr, cc, landuse, gt, cls.crs);
    const auto p = geo::raster_placement(cls, classes_path);
    char line[256];
    std::snprintf(line, sizeof line,
                  "image rows %ld columns %ld; centre latitude %.6f longitude %.6f (deg, E+); "
                  "grid rotation %.4f deg\n",
                  rows, columns, p.latitude_deg, p.longitude_deg, p.grid_rotation_deg);
    report << line;
}

void points_step(const PointsRequest& rq, std::ostream& report) {
    const auto rules = read_class_rules(rq.rules_path);
    const auto cls = geo::read_geo_raster(rq.classes_path, geo::Bands::First);
    const auto classes = integers(cls);
    std::vector<int> other = classes;  // a masked pixel agrees with no class
    if (!rq.mask_path.empty()) {
        const auto mask = union_of({rq.mask_path}, cls.rows, cls.columns);
        for (std::size_t i = 0; i < other.size(); ++i)
            if (mask[i]) other[i] = -1;
    }
    int highest = 0;
    for (const auto& r : rules.rules) highest = std::max(highest, r.id);
    const auto pts = pick_control_points(classes, cls.rows, cls.columns, other, highest,
                                         rq.per_class, rq.seed, rq.margin, 1);
    for (const bool fit : {true, false}) {
        io::Cpt cpt;
        std::map<int, int> number;
        for (const auto& p : pts) {
            const int n = ++number[p.cls];
            if (p.fit != fit) continue;
            const auto* rule = rules.by_id(p.cls);
            char name[128];
            std::snprintf(name, sizeof name, "%s_%02d", rule ? rule->name.c_str() : "class", n);
            cpt.points.push_back({name, double(p.row), double(p.column), double(p.row),
                                  double(p.column), 0.0, fit ? "fit half" : "held-out half", 0});
        }
        write_atomically(rq.prefix + (fit ? "_fit.cpt" : "_held.cpt"),
                         [&](std::ostream& out) { io::write_cpt(out, cpt); });
    }
    std::map<int, int> n;
    for (const auto& p : pts) ++n[p.cls];
    for (const auto& r : rules.rules) report << r.name << " " << n[r.id] << " points\n";
}

void fit_step(const std::string& cpt_path, const std::string& dark_path,
              const std::string& base_path, const std::string& reference_path,
              std::ostream& out) {
    const auto cpt = io::read_cpt_file(cpt_path);
    const auto dark = image::read_image(dark_path);
    const auto base = image::read_image(base_path);
    const auto ref = image::read_image(reference_path);
    if (ref.channels < base.channels)
        throw DataError({reference_path, 0}, "fewer bands than the synthetic images' " +
                                                 std::to_string(base.channels));
    std::vector<std::string> names;
    for (const auto& p : cpt.points) {
        const auto name = p.name.substr(0, p.name.rfind('_'));
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    out << "# class, then the reflectance scale of each band (least squares on " << cpt_path
        << ")\n";
    for (const auto& name : names) {
        out << name;
        for (int b = 0; b < base.channels; ++b) {
            char v[64];
            std::snprintf(v, sizeof v, " %.6g",
                          fit_reflectance_scale(class_values(dark, b, cpt, cpt_path, name, true),
                                                class_values(base, b, cpt, cpt_path, name, true),
                                                class_values(ref, b, cpt, cpt_path, name, false),
                                                {cpt_path, 0},
                                                "class " + name + ", band " + std::to_string(b + 1)));
            out << v;
        }
        out << "\n";
    }
}

void ems_step(const std::string& materials_path, const std::string& snd_path,
              const std::string& scales_path, const std::string& outdir) {
    const auto materials = read_materials(materials_path);
    const auto snd = io::read_snd_file(snd_path);
    const auto scales = scales_path == "-" ? std::map<std::string, std::vector<double>>{}
                                           : read_scales(scales_path, snd.bands.size());
    write_material_ems(materials, snd, scales, outdir,
                       "from " + materials_path +
                           (scales_path == "-" ? std::string() : " x the scales of " + scales_path));
}

void score_step(const ScoreRequest& rq, std::ostream& out) {
    const auto rules = read_class_rules(rq.rules_path);
    const auto syn = image::read_image(rq.synthetic_path);
    const auto ref = image::read_image(rq.reference_path);
    const auto cls = geo::read_geo_raster(rq.classes_path, geo::Bands::First);
    if (cls.rows != syn.rows || cls.columns != syn.columns)
        throw DataError({rq.classes_path, 0}, "the class map differs in size from the images");
    ScoreInput in;
    in.synthetic = &syn;
    in.reference = &ref;
    in.classes = integers(cls);
    in.mask = union_of(rq.mask_paths, syn.rows, syn.columns);
    in.rules = &rules;
    io::Cpt cpt;
    if (!rq.points_path.empty()) {
        cpt = io::read_cpt_file(rq.points_path);
        in.points = &cpt;
        in.points_path = rq.points_path;
    }
    in.bands = rq.bands > 0 ? rq.bands : std::min(syn.channels, ref.channels);
    write_scores(out, score(in));
}

namespace {

// The 2nd and 98th percentiles of one band.
std::pair<double, double> stretch_of(const image::Image& img, int b) {
    std::vector<float> v(img.data.begin() + b * img.plane_size(),
                         img.data.begin() + (b + 1) * img.plane_size());
    std::sort(v.begin(), v.end());
    const double lo = v[static_cast<std::size_t>(0.02 * (v.size() - 1))];
    double hi = v[static_cast<std::size_t>(0.98 * (v.size() - 1))];
    if (hi <= lo) hi = lo + 1;
    return {lo, hi};
}

}  // namespace

void side_by_side_step(const std::string& synthetic_path, const std::string& reference_path,
                       const std::vector<int>& bands, const std::string& out_path) {
    const auto syn = image::read_image(synthetic_path);
    const auto ref = image::read_image(reference_path);
    if (bands.size() != 3) throw UsageError("side-by-side takes three bands");
    if (syn.rows != ref.rows || syn.columns != ref.columns)
        throw DataError({synthetic_path, 0}, "differs in size from " + reference_path);
    constexpr long kGap = 8;
    image::Image out(syn.rows, 2 * syn.columns + kGap, 3, 255.0f);
    for (int k = 0; k < 3; ++k) {
        const int b = bands[k] - 1;
        if (b < 0 || b >= syn.channels || b >= ref.channels)
            throw DataError({synthetic_path, 0}, "no band " + std::to_string(bands[k]));
        const auto [lo, hi] = stretch_of(ref, b);
        for (long y = 0; y < syn.rows; ++y)
            for (long x = 0; x < syn.columns; ++x) {
                auto scale = [&](double v) {
                    return static_cast<float>(std::round(std::clamp((v - lo) / (hi - lo), 0.0, 1.0) * 255));
                };
                out.at(k, y, x) = scale(syn.at(b, y, x));
                out.at(k, y, x + syn.columns + kGap) = scale(ref.at(b, y, x));
            }
    }
    image::write_counts(out_path, out, 8);
}

void difference_step(const std::string& synthetic_path, const std::string& reference_path,
                     int band, double range, const std::vector<std::string>& mask_paths,
                     const std::string& out_path) {
    const auto syn = image::read_image(synthetic_path);
    const auto ref = image::read_image(reference_path);
    if (syn.rows != ref.rows || syn.columns != ref.columns)
        throw DataError({synthetic_path, 0}, "differs in size from " + reference_path);
    const int b = band - 1;
    if (b < 0 || b >= syn.channels || b >= ref.channels)
        throw DataError({synthetic_path, 0}, "no band " + std::to_string(band));
    if (!(range > 0)) throw UsageError("the range must be above 0");
    const auto mask = union_of(mask_paths, syn.rows, syn.columns);
    image::Image out(syn.rows, syn.columns, 3, 0.0f);
    for (long y = 0; y < syn.rows; ++y)
        for (long x = 0; x < syn.columns; ++x) {
            float rgb[3] = {160, 160, 160};
            if (!mask[y * syn.columns + x]) {
                const double t = std::clamp((syn.at(b, y, x) - ref.at(b, y, x)) / range, -1.0, 1.0);
                const float fade = static_cast<float>(std::round(255 * (1 - std::abs(t))));
                rgb[0] = t > 0 ? 255 : fade;  // red: the prediction too bright
                rgb[1] = fade;
                rgb[2] = t < 0 ? 255 : fade;  // blue: too dark
            }
            for (int k = 0; k < 3; ++k) out.at(k, y, x) = rgb[k];
        }
    image::write_counts(out_path, out, 8);
}

void pairs_step(const std::string& rules_path, const std::string& synthetic_path,
                const std::string& reference_path, const std::string& classes_path,
                const std::vector<std::string>& mask_paths, int band, long step,
                std::ostream& out) {
    const auto rules = read_class_rules(rules_path);
    const auto syn = image::read_image(synthetic_path);
    const auto ref = image::read_image(reference_path);
    const auto cls = geo::read_geo_raster(classes_path, geo::Bands::First);
    if (cls.rows != syn.rows || cls.columns != syn.columns || ref.rows != syn.rows ||
        ref.columns != syn.columns)
        throw DataError({classes_path, 0}, "the images and the class map differ in size");
    const int b = band - 1;
    if (b < 0 || b >= syn.channels || b >= ref.channels)
        throw DataError({synthetic_path, 0}, "no band " + std::to_string(band));
    if (step < 1) throw UsageError("the step must be at least 1");
    const auto mask = union_of(mask_paths, syn.rows, syn.columns);
    out << "# class synthetic reference (band " << band << ", every " << step
        << "th clear pixel)\n";
    for (std::size_t i = 0; i < syn.plane_size(); i += static_cast<std::size_t>(step)) {
        if (mask[i]) continue;
        const auto* rule = rules.by_id(static_cast<int>(std::lround(cls.values[i])));
        if (!rule) continue;
        out << rule->name << " " << syn.data[b * syn.plane_size() + i] << " "
            << ref.data[b * syn.plane_size() + i] << "\n";
    }
}

namespace {

// The value at fraction q of sorted values (nearest rank below).
double quantile(const std::vector<double>& sorted, double q) {
    return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

}  // namespace

void stats_step(const std::string& rules_path, const std::string& image_path,
                const std::string& classes_path, const std::vector<std::string>& mask_paths,
                std::ostream& out) {
    const auto rules = read_class_rules(rules_path);
    const auto img = image::read_image(image_path);
    const auto cls = geo::read_geo_raster(classes_path, geo::Bands::First);
    if (cls.rows != img.rows || cls.columns != img.columns)
        throw DataError({classes_path, 0}, "the class map differs in size from " + image_path);
    const auto classes = integers(cls);
    const auto mask = union_of(mask_paths, img.rows, img.columns);
    out << "# class band n mean std p01 median p99\n";
    std::vector<std::pair<std::string, int>> scopes{{"all", 0}};
    for (const auto& r : rules.rules) scopes.emplace_back(r.name, r.id);
    for (const auto& [name, id] : scopes)
        for (int b = 0; b < img.channels; ++b) {
            std::vector<double> v;
            for (std::size_t i = 0; i < img.plane_size(); ++i)
                if (!mask[i] && classes[i] != 0 && (id == 0 || classes[i] == id))
                    v.push_back(img.data[b * img.plane_size() + i]);
            if (v.empty()) continue;
            std::sort(v.begin(), v.end());
            double sum = 0, sq = 0;
            for (double x : v) sum += x;
            const double mean = sum / v.size();
            for (double x : v) sq += (x - mean) * (x - mean);
            char line[256];
            std::snprintf(line, sizeof line, "%s %d %zu %.3f %.3f %.1f %.1f %.1f\n",
                          name.c_str(), b + 1, v.size(), mean, std::sqrt(sq / v.size()),
                          quantile(v, 0.01), quantile(v, 0.5), quantile(v, 0.99));
            out << line;
        }
}

void crosstab_step(const std::string& rules_a, const std::string& classes_a,
                   const std::string& rules_b, const std::string& classes_b,
                   const std::vector<std::string>& mask_paths, std::ostream& out) {
    const auto ra = read_class_rules(rules_a);
    const auto rb = read_class_rules(rules_b);
    const auto ca = geo::read_geo_raster(classes_a, geo::Bands::First);
    const auto cb = geo::read_geo_raster(classes_b, geo::Bands::First);
    if (ca.rows != cb.rows || ca.columns != cb.columns)
        throw DataError({classes_b, 0}, "differs in size from " + classes_a);
    const auto a = integers(ca), b = integers(cb);
    const auto mask = union_of(mask_paths, ca.rows, ca.columns);
    std::map<std::pair<int, int>, long> n;
    std::map<int, long> total;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!mask[i] && a[i] != 0 && b[i] != 0) ++n[{a[i], b[i]}], ++total[a[i]];
    out << "# class_a class_b n fraction_of_a\n";
    for (const auto& x : ra.rules)
        for (const auto& y : rb.rules) {
            const long k = n[{x.id, y.id}];
            char line[256];
            std::snprintf(line, sizeof line, "%s %s %ld %.4f\n", x.name.c_str(), y.name.c_str(),
                          k, total[x.id] ? double(k) / total[x.id] : 0.0);
            out << line;
        }
}

}  // namespace sigchain::landcover
