// olinda_scene: the Olinda scene's preparation steps (land-use classification, control
// points, reflectance-scale fit, .ems curves); see README.md in this folder. Not an
// installed tool: a scene helper built from this folder.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "compare/compare.hpp"
#include "core/error.hpp"
#include "image/image.hpp"
#include "io/cpt.hpp"
#include "landcover/classify.hpp"
#include "landcover/fit.hpp"
#include "landcover/preview.hpp"
#include "landcover/raster.hpp"

namespace lc = sigchain::landcover;
using sigchain::io::ControlPoint;

namespace {

constexpr int kBands = 4;  // ETM+ bands 1-4 are rendered

int classify(const std::string& etm_path, const std::string& dem_path, const std::string& dir) {
    const lc::GeoRaster etm = lc::read_geo_raster(etm_path);
    const lc::GeoRaster dem = lc::read_geo_raster(dem_path);
    const auto classes = lc::classify_raster(etm, lc::Rule{});
    const auto blocks = lc::majority_on_dem_blocks(classes, etm.rows, etm.columns,
                                                   etm.geotransform, dem.rows, dem.columns,
                                                   dem.geotransform);
    lc::write_class_raster(dir + "/classes_image.tif", etm.rows, etm.columns, classes,
                           etm.geotransform, etm.crs_wkt);
    lc::write_class_raster(dir + "/landuse.tif", dem.rows, dem.columns, blocks, dem.geotransform,
                           dem.crs_wkt);
    const auto fi = lc::class_fractions(classes);
    const auto fd = lc::class_fractions(blocks);
    std::printf("class          image_fraction  dem_block_fraction\n");
    for (int k = 1; k <= lc::kClassCount; ++k)
        std::printf("%d %-12s %14.4f %19.4f\n", k, lc::class_name(lc::LandCover(k)), fi[k - 1],
                    fd[k - 1]);
    const auto p = lc::raster_placement(etm);
    std::printf("image rows %ld columns %ld; centre latitude %.6f longitude %.6f (deg, E+); "
                "grid rotation %.4f deg\n",
                etm.rows, etm.columns, p.latitude_deg, p.longitude_deg, p.grid_rotation_deg);
    return 0;
}

// Class of the DEM block each image pixel's centre falls in (the material trace sees).
std::vector<int> block_class_per_pixel(const lc::GeoRaster& img, const lc::GeoRaster& lu) {
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

void write_points(const std::string& path, const std::vector<lc::ClassPoint>& pts, bool fit) {
    sigchain::io::Cpt cpt;
    std::map<int, int> number;
    for (const auto& p : pts) {
        const int n = ++number[p.cls];
        if (p.fit != fit) continue;
        char name[64];
        std::snprintf(name, sizeof name, "%s_%02d", lc::class_name(lc::LandCover(p.cls)), n);
        cpt.points.push_back({name, double(p.row), double(p.column), double(p.row),
                              double(p.column), 0.0, fit ? "fit half" : "held-out half", 0});
    }
    std::ofstream out(path);
    sigchain::io::write_cpt(out, cpt);
    if (!out) throw sigchain::IoError(path + ": cannot write");
}

int points(const std::string& classes_path, const std::string& landuse_path, int per_class,
           unsigned seed, long margin, const std::string& prefix) {
    const lc::GeoRaster img = lc::read_geo_raster(classes_path);
    const lc::GeoRaster lu = lc::read_geo_raster(landuse_path);
    std::vector<int> classes(img.values.begin(), img.values.end());
    const auto other = block_class_per_pixel(img, lu);
    const auto pts = lc::pick_control_points(classes, img.rows, img.columns, other,
                                             lc::kClassCount, per_class, seed, margin, 1);
    write_points(prefix + "_fit.cpt", pts, true);
    write_points(prefix + "_held.cpt", pts, false);
    std::map<int, int> n;
    for (const auto& p : pts) ++n[p.cls];
    for (const auto& [k, v] : n) std::printf("%s %d points\n", lc::class_name(lc::LandCover(k)), v);
    return 0;
}

// Values of one band at the control points of one class (class = name before '_').
std::vector<double> values(const sigchain::image::Image& img, int band,
                           const std::vector<ControlPoint>& pts, const std::string& cls,
                           bool synthetic) {
    std::vector<double> v;
    for (const auto& p : pts) {
        if (p.name.substr(0, p.name.find('_')) != cls) continue;
        v.push_back(sigchain::compare::control_point_value(
            img, band, synthetic ? p.synthetic_row : p.reference_row,
            synthetic ? p.synthetic_column : p.reference_column, p.radius_px, {"cpt", p.line},
            "image"));
    }
    return v;
}

int fit(const std::string& cpt_path, const std::string& dark_path, const std::string& base_path,
        const std::string& ref_path) {
    const auto cpt = sigchain::io::read_cpt_file(cpt_path);
    const auto dark = sigchain::image::read_image(dark_path);
    const auto base = sigchain::image::read_image(base_path);
    const auto ref = sigchain::image::read_image(ref_path);
    std::printf("# class  scale_band1 scale_band2 scale_band3 scale_band4 (least squares on %s)\n",
                cpt_path.c_str());
    for (int k = 1; k <= lc::kClassCount; ++k) {
        const std::string name = lc::class_name(lc::LandCover(k));
        std::printf("%s", name.c_str());
        for (int b = 0; b < kBands; ++b)
            std::printf(" %.6g", lc::fit_reflectance_scale(values(dark, b, cpt.points, name, true),
                                                           values(base, b, cpt.points, name, true),
                                                           values(ref, b, cpt.points, name, false)));
        std::printf("\n");
    }
    return 0;
}

// ETM+ band edges (um, half-power; /work/shared/data/olinda/README.md).
constexpr double kEdges[kBands][2] = {{0.450, 0.515}, {0.525, 0.605}, {0.630, 0.690},
                                      {0.775, 0.900}};

std::map<std::string, std::vector<double>> read_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw sigchain::IoError(path + ": cannot open");
    std::map<std::string, std::vector<double>> t;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        line = line.substr(0, line.find('#'));
        std::istringstream s(line);
        std::string name;
        if (!(s >> name)) continue;
        std::vector<double> v(kBands);
        for (double& x : v)
            if (!(s >> x)) throw sigchain::DataError({path, n}, "expected a class and 4 values");
        t[name] = v;
    }
    return t;
}

int ems(const std::string& refl_path, const std::string& scales_path, const std::string& dir) {
    const auto refl = read_table(refl_path);
    const auto scales = scales_path == "-" ? decltype(refl){} : read_table(scales_path);
    for (const auto& [name, rho] : refl) {
        const std::string path = dir + "/" + name + ".ems";
        std::ofstream out(path);
        out << "# " << name << ": reflectance per ETM+ band, flat inside each band's half-power "
            << "edges (from " << refl_path << (scales.empty() ? "" : " x " + scales_path)
            << "); emissivity = 1 - reflectance\n1\n";
        for (int a = 0; a <= 90; ++a) out << "1\n";
        out << "CURVE_BEGIN\n";
        for (int b = 0; b < kBands; ++b) {
            const double s = scales.count(name) ? scales.at(name)[b] : 1.0;
            const double e = std::clamp(1.0 - rho[b] * s, 0.0, 1.0);
            out << kEdges[b][0] << " " << e << "\n" << kEdges[b][1] << " " << e << "\n";
        }
        out << "CURVE_END\n";
        if (!out) throw sigchain::IoError(path + ": cannot write");
    }
    return 0;
}

// The synthetic counts beside the reference, bands 3, 2, 1 as red, green, blue.
int preview(const std::string& synthetic, const std::string& reference, const std::string& out) {
    const auto image = sigchain::landcover::side_by_side(sigchain::image::read_image(synthetic),
                                                         sigchain::image::read_image(reference),
                                                         {3, 2, 1});
    sigchain::image::write_counts(out, image, 8);
    return 0;
}

int usage() {
    std::cerr << "usage: olinda_scene classify ETM.tif DEM.tif OUTDIR\n"
                 "       olinda_scene points CLASSES_IMAGE.tif LANDUSE.tif PER_CLASS SEED MARGIN "
                 "PREFIX\n"
                 "       olinda_scene fit FIT.cpt DARK.tif BASE.tif REFERENCE.tif\n"
                 "       olinda_scene ems REFLECTANCE.txt SCALES.txt|- OUTDIR\n"
                 "       olinda_scene preview SYNTHETIC.tif REFERENCE.tif OUT.png\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> a(argv + 1, argv + argc);
    try {
        if (a.size() == 4 && a[0] == "classify") return classify(a[1], a[2], a[3]);
        if (a.size() == 7 && a[0] == "points")
            return points(a[1], a[2], std::stoi(a[3]), std::stoul(a[4]), std::stol(a[5]), a[6]);
        if (a.size() == 5 && a[0] == "fit") return fit(a[1], a[2], a[3], a[4]);
        if (a.size() == 4 && a[0] == "ems") return ems(a[1], a[2], a[3]);
        if (a.size() == 4 && a[0] == "preview") return preview(a[1], a[2], a[3]);
        return usage();
    } catch (const std::exception& e) {
        std::cerr << "olinda_scene: " << e.what() << "\n";
        return 1;
    }
}
