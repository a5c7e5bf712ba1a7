// The Olinda scene's preparation steps: classification, control points, the fit of the
// reflectance scales, the .ems curves and the preview.
#include "landcover/olinda.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "compare/compare.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "geo/raster.hpp"
#include "image/image.hpp"
#include "io/cpt.hpp"
#include "landcover/classify.hpp"
#include "landcover/fit.hpp"
#include "landcover/preview.hpp"
#include "landcover/raster.hpp"

namespace sigchain::landcover {

namespace {

// printf-style formatting into a string (the reports' fixed column layouts).
std::string format(const char* fmt, ...) {
    char buffer[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buffer, sizeof buffer, fmt, args);
    va_end(args);
    return buffer;
}

geo::GeoRaster read_north_up(const std::string& path) {
    geo::GeoRaster r = geo::read_geo_raster(path);
    geo::require_north_up_with_crs(r, path);
    return r;
}

// Class of the DEM block each image pixel's centre falls in (the material trace sees).
std::vector<int> block_class_per_pixel(const geo::GeoRaster& img, const geo::GeoRaster& lu) {
    std::vector<int> out(static_cast<std::size_t>(img.rows) * img.columns, 0);
    const auto& g = img.geotransform;
    const auto& d = lu.geotransform;
    for (long r = 0; r < img.rows; ++r)
        for (long c = 0; c < img.columns; ++c) {
            const double x = g[0] + g[1] * (c + 0.5), y = g[3] + g[5] * (r + 0.5);
            const long bc = static_cast<long>(std::floor((x - d[0]) / d[1] - 0.5));
            const long br = static_cast<long>(std::floor((y - d[3]) / d[5] - 0.5));
            if (br >= 0 && bc >= 0 && br < lu.rows - 1 && bc < lu.columns - 1)
                out[r * img.columns + c] = static_cast<int>(lu.at(0, br, bc));
        }
    return out;
}

void write_points(const std::string& path, const std::vector<ClassPoint>& pts, bool fit) {
    io::Cpt cpt;
    std::map<int, int> number;
    for (const auto& p : pts) {
        const int n = ++number[p.cls];
        if (p.fit != fit) continue;
        const std::string name = format("%s_%02d", class_name(LandCover(p.cls)), n);
        cpt.points.push_back({name, double(p.row), double(p.column), double(p.row),
                              double(p.column), 0.0, fit ? "fit half" : "held-out half", 0});
    }
    write_atomically(path, [&](std::ostream& out) { io::write_cpt(out, cpt); });
}

// Values of one band at the control points of one class (class = name before '_').
std::vector<double> values(const image::Image& img, int band, const io::Cpt& cpt,
                           const std::string& cpt_path, const std::string& cls, bool synthetic) {
    std::vector<double> v;
    for (const auto& p : cpt.points) {
        if (p.name.substr(0, p.name.find('_')) != cls) continue;
        v.push_back(
            compare::control_point_value(img, band, synthetic ? p.synthetic_row : p.reference_row,
                                         synthetic ? p.synthetic_column : p.reference_column,
                                         p.radius_px, {cpt_path, p.line}, "image"));
    }
    return v;
}

// ETM+ band edges (um, half-power; the Landsat data README, cited in
// data/scenes/olinda/README.md).
constexpr double kEdges[kEtmBands][2] = {
    {0.450, 0.515}, {0.525, 0.605}, {0.630, 0.690}, {0.775, 0.900}};

// A table of "CLASS v1 v2 v3 v4" rows ('#' starts a comment).
std::map<std::string, std::vector<double>> read_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw IoError(path + ": cannot open");
    std::map<std::string, std::vector<double>> t;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        line = line.substr(0, line.find('#'));
        std::istringstream s(line);
        std::string name;
        if (!(s >> name)) continue;
        std::vector<double> v(kEtmBands);
        for (double& x : v)
            if (!(s >> x)) throw DataError({path, n}, "expected a class and 4 values");
        t[name] = v;
    }
    return t;
}

}  // namespace

void classify_scene(const std::string& etm_path, const std::string& dem_path,
                    const std::string& outdir, std::ostream& report) {
    const geo::GeoRaster etm = read_north_up(etm_path);
    const geo::GeoRaster dem = read_north_up(dem_path);
    const auto classes = classify_raster(etm, Rule{}, etm_path);
    const auto blocks = majority_on_dem_blocks(classes, etm.rows, etm.columns, etm.geotransform,
                                               dem.rows, dem.columns, dem.geotransform);
    write_class_raster(outdir + "/classes_image.tif", etm.rows, etm.columns, classes,
                       etm.geotransform, etm.crs);
    write_class_raster(outdir + "/landuse.tif", dem.rows, dem.columns, blocks, dem.geotransform,
                       dem.crs);
    const auto fi = class_fractions(classes);
    const auto fd = class_fractions(blocks);
    report << "class          image_fraction  dem_block_fraction\n";
    for (int k = 1; k <= kClassCount; ++k)
        report << format("%d %-12s %14.4f %19.4f\n", k, class_name(LandCover(k)), fi[k - 1],
                         fd[k - 1]);
    const auto p = geo::raster_placement(etm, etm_path);
    report << format(
        "image rows %ld columns %ld; centre latitude %.6f longitude %.6f (deg, E+); "
        "grid rotation %.4f deg\n",
        etm.rows, etm.columns, p.latitude_deg, p.longitude_deg, p.grid_rotation_deg);
}

void write_control_points(const ControlPointRequest& rq, std::ostream& report) {
    const geo::GeoRaster img = read_north_up(rq.classes_path);
    const geo::GeoRaster lu = read_north_up(rq.landuse_path);
    std::vector<int> classes(img.values.begin(), img.values.end());
    const auto other = block_class_per_pixel(img, lu);
    const auto pts = pick_control_points(classes, img.rows, img.columns, other, kClassCount,
                                         rq.per_class, rq.seed, rq.margin, 1);
    write_points(rq.prefix + "_fit.cpt", pts, true);
    write_points(rq.prefix + "_held.cpt", pts, false);
    std::map<int, int> n;
    for (const auto& p : pts) ++n[p.cls];
    for (const auto& [k, v] : n) report << format("%s %d points\n", class_name(LandCover(k)), v);
}

void fit_scales(const std::string& cpt_path, const std::string& dark_path,
                const std::string& base_path, const std::string& reference_path,
                std::ostream& out) {
    const auto cpt = io::read_cpt_file(cpt_path);
    const auto dark = image::read_image(dark_path);
    const auto base = image::read_image(base_path);
    const auto ref = image::read_image(reference_path);
    out << format(
        "# class  scale_band1 scale_band2 scale_band3 scale_band4 (least squares "
        "on %s)\n",
        cpt_path.c_str());
    for (int k = 1; k <= kClassCount; ++k) {
        const std::string name = class_name(LandCover(k));
        out << name;
        for (int b = 0; b < kEtmBands; ++b)
            out << format(" %.6g",
                          fit_reflectance_scale(values(dark, b, cpt, cpt_path, name, true),
                                                values(base, b, cpt, cpt_path, name, true),
                                                values(ref, b, cpt, cpt_path, name, false),
                                                {cpt_path, 0},
                                                "class " + name + ", band " + std::to_string(b + 1)));
        out << "\n";
    }
}

void write_ems_curves(const std::string& reflectance_path, const std::string& scales_path,
                      const std::string& outdir) {
    const auto refl = read_table(reflectance_path);
    const auto scales = scales_path == "-" ? decltype(refl){} : read_table(scales_path);
    for (const auto& [name, rho] : refl) {
        const std::string path = outdir + "/" + name + ".ems";
        AtomicOutput file(path);
        std::ostream& out = file.stream();
        out << "# " << name << ": reflectance per ETM+ band, flat inside each band's half-power "
            << "edges (from " << reflectance_path << (scales.empty() ? "" : " x " + scales_path)
            << "); emissivity = 1 - reflectance\n1\n";
        for (int a = 0; a <= 90; ++a) out << "1\n";
        out << "CURVE_BEGIN\n";
        for (int b = 0; b < kEtmBands; ++b) {
            const double s = scales.count(name) ? scales.at(name)[b] : 1.0;
            const double e = std::clamp(1.0 - rho[b] * s, 0.0, 1.0);
            out << kEdges[b][0] << " " << e << "\n" << kEdges[b][1] << " " << e << "\n";
        }
        out << "CURVE_END\n";
        file.commit();
    }
}

void write_preview(const std::string& synthetic_path, const std::string& reference_path,
                   const std::string& out_path) {
    const auto preview = side_by_side(image::read_image(synthetic_path),
                                      image::read_image(reference_path), {3, 2, 1});
    image::write_counts(out_path, preview, 8);
}

}  // namespace sigchain::landcover
