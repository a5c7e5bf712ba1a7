// Materials as trace uses them: .mat entries with their .ems/.ext curves sampled on the
// render's spectral grid, fall-off, specularity and lobe (material.hpp; mat(5), ems(5),
// ext(5)).
#include "radiometry/material.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "io/brdf.hpp"
#include "io/ext.hpp"

namespace sigchain::radiometry {

namespace {

// Ids above this are refused: the id -> material index is a plain vector (constant time).
using io::kMaxMaterialId;  // mat(5); the reader enforces it
constexpr double kKmPerCm = 1e-5;

std::string resolve(const std::string& mat_path, const std::string& file) {
    std::filesystem::path p(file);
    if (p.is_absolute() || mat_path.empty() || mat_path == "-") return file;
    return (std::filesystem::path(mat_path).parent_path() / p).string();
}

std::string label(const io::Material& m) {
    return "material '" + m.name + "' (" + std::to_string(m.id) + ")";
}

// Reads a curve file with `read`, turning its failure into an error at the tag's line.
template <class T, class Read>
const T& cached(std::map<std::string, T>& cache, const std::string& path, const io::Material& m,
                const std::string& mat_path, const char* tag, Read read) {
    auto it = cache.find(path);
    if (it != cache.end()) return it->second;
    std::string prefix = label(m) + ": cannot read " + std::string(tag) + " " + path + ": ";
    try {
        return cache.emplace(path, read(path)).first->second;
    } catch (const IoError& e) {
        // The reader's message starts with the path, already in ours.
        std::string why = e.what();
        if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
        throw IoError(SourceLocation{mat_path, m.line_of(tag)}.str() + ": " + prefix + why);
    } catch (const Error& e) {
        throw DataError({mat_path, m.line_of(tag)}, prefix + e.what());
    }
}

// The table model's Brdf, one per TABLE_FILE (brdf(5)), read with TABLE_FILE's line in
// its errors.
Brdf table_brdf(const io::Material& m, const std::string& mat_path,
                std::map<std::string, Brdf>& tables) {
    std::string path = resolve(mat_path, m.table_file);
    auto read = [](const std::string& p) {
        io::BrdfTable t = io::read_brdf_file(p);
        try {
            return Brdf::table(t);
        } catch (const std::invalid_argument&) {
            throw DataError({p, 0}, "expected a BRDF table with a value above 0, found none");
        }
    };
    return cached(tables, path, m, mat_path, "TABLE_FILE", read);
}

// The Brdf of the entry's effective model (mat(5) REFLECTANCE MODELS).
Brdf brdf_of(const io::Material& m, const io::Ems& ems, const std::string& mat_path,
             std::map<std::string, Brdf>& tables) {
    switch (io::effective_model(m)) {
        case io::ReflectanceModel::Lambertian:
            return Brdf::lambertian();
        case io::ReflectanceModel::Dirsig:
            return Brdf::delta();
        case io::ReflectanceModel::Cone:
            if (ems.specular_lobe.size() == static_cast<std::size_t>(io::kLobeRowCount)) {
                std::array<double, 7> radii{}, depth{};
                for (int i = 0; i < io::kLobeRowCount; ++i) {
                    radii[i] = ems.specular_lobe[i].base_radius_deg;
                    depth[i] = ems.specular_lobe[i].depth;
                }
                return io::lobe_depth_used(ems) ? Brdf::linear_cone(radii, depth)
                                                : Brdf::linear_cone(radii);
            }
            return Brdf::cone(m.cone_half_angle_deg.value_or(0));
        case io::ReflectanceModel::Phong:
            return Brdf::phong(m.phong_exponent.value_or(0));
        case io::ReflectanceModel::Exponential:
            return Brdf::exponential(m.exponential_width_deg.value_or(0));
        case io::ReflectanceModel::Table:
            return table_brdf(m, mat_path, tables);
    }
    throw std::logic_error("brdf_of: unknown model");
}

// Relative spread of the curves' mean reflectances 1 - eps (over the grid): their
// standard deviation over their mean (0 with one curve), the default Gaussian texture
// sigma (mat(5) GAUSSIAN TEXTURE).
double curve_spread(const std::vector<std::vector<double>>& emissivity) {
    std::vector<double> r;
    for (const auto& e : emissivity) {
        double sum = 0;
        for (double x : e) sum += 1 - x;
        r.push_back(e.empty() ? 0 : sum / static_cast<double>(e.size()));
    }
    if (r.size() < 2) return 0;
    double mean = 0, var = 0;
    for (double x : r) mean += x / static_cast<double>(r.size());
    for (double x : r) var += (x - mean) * (x - mean) / static_cast<double>(r.size());
    return mean > 0 ? std::sqrt(var) / mean : 0;
}

// Fall-off F(theta): linear between the values at whole degrees, theta clamped to [0, 90].
double fall_off_at(const std::array<double, io::kFallOffCount>& f, double theta_deg) {
    double x = std::clamp(theta_deg, 0.0, 90.0);
    int i = std::min(static_cast<int>(x), io::kFallOffCount - 2);
    double t = x - i;
    return f[i] + t * (f[i + 1] - f[i]);
}

// The fall-off's projected-solid-angle mean 2 Int_0^90 F cos sin d(theta) (midpoint,
// 0.1-deg steps: exact to 1e-6 for F linear between whole degrees) and whether F = 1.
void fall_off_statistics(MaterialOptics& o) {
    o.flat_fall_off = std::all_of(o.fall_off.begin(), o.fall_off.end(),
                                  [](double f) { return f == 1.0; });
    if (o.flat_fall_off) {
        o.mean_fall_off = 1;
        return;
    }
    constexpr int kSteps = 900;
    double sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * 90.0 / kSteps;
        sum += fall_off_at(o.fall_off, theta) * std::sin(2 * theta * kRadPerDeg);
    }
    o.mean_fall_off = sum * (90.0 / kSteps) * kRadPerDeg;  // Int F sin(2 theta) d(theta)
}

// SPECULAR_CURVE (mat(5)): a curve of the entry's .ems, and not with a cone whose depth
// column already sets the specular reflectance. DataError at the tag's line.
void set_specular_curve(MaterialOptics& o, const io::Material& m, const io::Ems& ems,
                        const std::string& mat_path) {
    if (!m.specular_curve) return;
    const long k = *m.specular_curve, n = static_cast<long>(ems.curves.size());
    const SourceLocation where{mat_path, m.specular_curve_line};
    if (k >= n)
        throw DataError(where, label(m) + ": expected SPECULAR_CURVE a curve of " +
                                   m.emissivity_file + " (0 to " + std::to_string(n - 1) +
                                   "), found " + std::to_string(k));
    if (o.brdf.has_depth())
        throw DataError(where, label(m) + ": SPECULAR_CURVE and the lobe depths of " +
                                   m.emissivity_file +
                                   " both set the specular reflectance; give one (depths of "
                                   "-999 leave it to SPECULAR_CURVE)");
    o.specular_curve = static_cast<int>(k);
}

// With a depth column the diffuse (1 - s)(1 - eps) and the cone's a_s (brdf.hpp) add up:
// more than 1 at some angle would reflect more than arrives (a negative Kirchhoff
// emissivity). Checked at every whole degree of specular angle, every curve and sample.
void check_depth_energy(const MaterialOptics& o, const io::Material& m,
                        const std::string& mat_path) {
    if (!o.brdf.has_depth()) return;
    double a_max = 0, r_max = 0;
    for (int deg = 0; deg <= 90; ++deg)
        a_max = std::max(a_max, o.brdf.depth_albedo(std::cos(deg * std::numbers::pi / 180)));
    for (const auto& e : o.emissivity)
        for (double x : e) r_max = std::max(r_max, 1 - x);
    const double total = (1 - o.specularity) * r_max + a_max;
    if (total > 1 + 1e-12)
        throw DataError({mat_path, m.line},
                        label(m) +
                            ": reflects more than it receives: (1 - SPECULARITY)(1 - "
                            "emissivity) + the cone depth's albedo 2 alpha (1 - sin "
                            "beta / beta) reaches " +
                            format_number(total));
}

}  // namespace

MaterialLibrary MaterialLibrary::load(const io::Mat& mat, const std::string& mat_path,
                                      const SpectralGrid& grid) {
    std::map<std::string, io::Ems> ems_cache;
    std::map<std::string, io::Ext> ext_cache;
    std::map<std::string, Brdf> tables;
    std::vector<MaterialOptics> out;
    for (const auto& m : mat.materials) {
        MaterialOptics o;
        o.id = m.id, o.name = m.name, o.mat_file = mat_path, o.line = m.line;
        o.texture_line = m.line_of("TEXTURE_FILE");
        const io::Ems& ems = cached(ems_cache, resolve(mat_path, m.emissivity_file), m, mat_path,
                                    "EMISSIVITY_FILE", io::read_ems_file);
        for (std::size_t c = 0; c < ems.curves.size(); ++c) {
            std::vector<double> e(grid.size());
            for (std::size_t k = 0; k < grid.size(); ++k)
                e[k] = io::emissivity(ems, static_cast<int>(c), grid.wavelength_um[k]);
            o.emissivity.push_back(std::move(e));
        }
        o.fall_off = ems.fall_off;
        o.brdf = brdf_of(m, ems, mat_path, tables);
        o.specularity = o.brdf.shape() == LobeShape::None ? 0 : m.specularity;
        set_specular_curve(o, m, ems, mat_path);
        check_depth_energy(o, m, mat_path);
        o.transmissive = m.optical != io::OpticalDescription::Opaque;
        if (o.transmissive) {
            const io::Ext& ext = cached(ext_cache, resolve(mat_path, m.extinction_file), m,
                                        mat_path, "EXTINCTION_FILE", io::read_ext_file);
            o.extinction_per_km.resize(grid.size());
            for (std::size_t k = 0; k < grid.size(); ++k)
                o.extinction_per_km[k] = io::extinction_per_km(ext, 0, grid.wavelength_um[k]);
        }
        o.thickness_cm = m.thickness_cm.value_or(0);
        o.double_sided = m.double_sided.value_or(true);
        o.gaussian_texture = m.use_gaussian_texture.value_or(false);
        if (o.gaussian_texture)
            o.gaussian_sigma = m.gaussian_texture_stddev.value_or(curve_spread(o.emissivity));
        if (!m.texture_file.empty())
            o.texture = read_texture_map(resolve(mat_path, m.texture_file), o);
        out.push_back(std::move(o));
    }
    return from_optics(std::move(out));
}

namespace {

// An error about material `m`: DataError at its .mat line, or std::invalid_argument for
// optics built in code (no file).
[[noreturn]] void material_error(const MaterialOptics& m, const std::string& what) {
    std::string message = "material '" + m.name + "' (" + std::to_string(m.id) + "): " + what;
    if (m.mat_file.empty()) throw std::invalid_argument(message);
    throw DataError({m.mat_file, m.line}, message);
}

}  // namespace

MaterialLibrary MaterialLibrary::from_optics(std::vector<MaterialOptics> materials) {
    for (auto& m : materials) fall_off_statistics(m);
    for (const auto& m : materials) {
        if (m.specular_curve >= static_cast<int>(m.emissivity.size()))
            material_error(m, "SPECULAR_CURVE " + std::to_string(m.specular_curve) +
                                  " is not one of its curves");
        if (m.specular_curve >= 0 && m.brdf.shape() == LobeShape::None)
            material_error(m, "SPECULAR_CURVE with REFLECTANCE_MODEL = lambertian");
    }
    MaterialLibrary lib;
    long max_id = -1;
    for (const auto& m : materials) {
        if (m.id < 0 || m.id > kMaxMaterialId)
            material_error(m, "MATERIAL_ID outside [0, " + std::to_string(kMaxMaterialId) + "]");
        max_id = std::max(max_id, m.id);
    }
    lib.m_index.assign(static_cast<std::size_t>(max_id + 1), -1);
    for (std::size_t i = 0; i < materials.size(); ++i) {
        int& slot = lib.m_index[static_cast<std::size_t>(materials[i].id)];
        if (slot >= 0) material_error(materials[i], "MATERIAL_ID used twice");
        slot = static_cast<int>(i);
    }
    lib.m_materials = std::move(materials);
    return lib;
}

const MaterialOptics* MaterialLibrary::find(long id) const {
    if (id < 0 || id >= static_cast<long>(m_index.size()) || m_index[id] < 0) return nullptr;
    return &m_materials[m_index[id]];
}

double MaterialOptics::fall_off_cos(double cos_theta) const {
    if (flat_fall_off) return 1;
    return fall_off_at(fall_off, std::acos(std::clamp(cos_theta, -1.0, 1.0)) * 180 / std::numbers::pi);
}

ReflectanceSplit MaterialOptics::split_weights(double cos_theta_o) const {
    ReflectanceSplit w;
    const LobeShape shape = brdf.shape();
    const double s = shape == LobeShape::None ? 0.0 : specularity;
    w.diffuse = 1 - s;
    w.specular = brdf.has_depth() ? brdf.depth_albedo(cos_theta_o) : s;
    w.delta = w.specular > 0 && shape == LobeShape::Delta;
    w.lobe = w.specular > 0 && shape != LobeShape::None && shape != LobeShape::Delta;
    if (w.lobe) w.lobe_probability = brdf.has_depth() ? w.specular / (w.specular + w.diffuse) : s;
    return w;
}

void MaterialOptics::directional_emissivity(int curve, double theta_deg,
                                            std::span<double> out) const {
    const std::vector<double>& e = emissivity.at(curve);
    const double f = fall_off_at(fall_off, theta_deg);
    if (split_reflectance()) {
        // Kirchhoff with the two parts apart: 1 - F [(1 - s) r_d Fbar + w_s r_s F].
        const ReflectanceSplit w = split_weights(std::cos(theta_deg * std::numbers::pi / 180));
        const std::vector<double>* es =
            specular_curve >= 0 ? &emissivity.at(specular_curve) : nullptr;
        std::size_t n = std::min(out.size(), e.size());
        for (std::size_t k = 0; k < n; ++k) {
            const double r_s = es ? 1 - (*es)[k] : 1.0;
            out[k] = 1 - f * (w.diffuse * (1 - e[k]) * mean_fall_off + w.specular * r_s * f);
        }
        return;
    }
    const double s = brdf.shape() == LobeShape::None ? 0.0 : specularity;
    const double albedo = f * ((1 - s) * mean_fall_off + s * f);  // rho_dh / (1 - eps)
    std::size_t n = std::min(out.size(), e.size());
    for (std::size_t k = 0; k < n; ++k) out[k] = 1 - (1 - e[k]) * albedo;
}

// rho = (1 - eps) F (opaque); (1 - eps) F (1 - t) for a transmissive slab (mat(5):
// r + a + t = 1). A negative thickness means the material's own THICKNESS.
void MaterialOptics::reflectance(int curve, double theta_deg, double thickness,
                                 std::span<double> out) const {
    if (!split_reflectance()) return diffuse_reflectance(curve, theta_deg, thickness, out);
    // What a uniform sky sees: (1 - s) rho_d + w_s rho_s.
    std::vector<double> rho_s(out.size());
    diffuse_reflectance(curve, theta_deg, thickness, out);
    specular_reflectance(theta_deg, thickness, rho_s);
    const ReflectanceSplit w = split_weights(std::cos(theta_deg * std::numbers::pi / 180));
    for (std::size_t k = 0; k < out.size(); ++k)
        out[k] = w.diffuse * out[k] + w.specular * rho_s[k];
}

void MaterialOptics::specular_reflectance(double theta_deg, double thickness,
                                          std::span<double> out) const {
    if (specular_curve >= 0) return diffuse_reflectance(specular_curve, theta_deg, thickness, out);
    if (!brdf.has_depth()) return diffuse_reflectance(0, theta_deg, thickness, out);
    // The depth's lobe is grey (emissivity units): F(theta) [(1 - t)], its energy in w_s.
    const double f = fall_off_at(fall_off, theta_deg);
    if (!transmissive) {
        std::fill(out.begin(), out.end(), f);
        return;
    }
    const double d_km = (thickness < 0 ? thickness_cm : thickness) * kKmPerCm;
    const double c = std::cos(theta_deg * std::numbers::pi / 180);
    const std::size_t n = std::min(out.size(), extinction_per_km.size());
    for (std::size_t k = 0; k < n; ++k)
        out[k] = f * (1 - io::transmittance(extinction_per_km[k], d_km, c));
}

void MaterialOptics::diffuse_reflectance(int curve, double theta_deg, double thickness,
                                         std::span<double> out) const {
    const std::vector<double>& e = emissivity.at(curve);
    double f = fall_off_at(fall_off, theta_deg);
    std::size_t n = std::min(out.size(), e.size());
    if (!transmissive) {
        for (std::size_t k = 0; k < n; ++k) out[k] = (1 - e[k]) * f;
        return;
    }
    double d_km = (thickness < 0 ? thickness_cm : thickness) * kKmPerCm;
    double c = std::cos(theta_deg * std::numbers::pi / 180);
    for (std::size_t k = 0; k < n; ++k)
        out[k] = (1 - e[k]) * f * (1 - io::transmittance(extinction_per_km[k], d_km, c));
}

// t = exp(-k d / |cos theta|) (ext(5); io::transmittance clamps |cos| at grazing). 0 for
// an opaque material. A negative thickness means the material's own THICKNESS.
void MaterialOptics::transmittance(double cos_theta, double thickness,
                                   std::span<double> out) const {
    if (!transmissive) {
        std::fill(out.begin(), out.end(), 0.0);
        return;
    }
    double d_km = (thickness < 0 ? thickness_cm : thickness) * kKmPerCm;
    std::size_t n = std::min(out.size(), extinction_per_km.size());
    for (std::size_t k = 0; k < n; ++k)
        out[k] = io::transmittance(extinction_per_km[k], d_km, cos_theta);
}

// z by Box-Muller from two splitmix64-hashed uniforms of (seed, key1, key2)
// (core/numeric.hpp; the constants tell this draw from trace's other random numbers).
double MaterialOptics::texture_gain(std::uint64_t seed, std::uint64_t key1,
                                    std::uint64_t key2) const {
    if (!gaussian_texture || gaussian_sigma <= 0) return 1;
    const std::uint64_t h = splitmix64(splitmix64(splitmix64(seed ^ 0x7465787475726531ULL) ^ key1) ^
                                       (key2 + 0x632be59bULL));
    const double u1 = unit_interval(h), u2 = unit_interval(splitmix64(h));
    const double z = box_muller(std::log1p(-u1), u2);  // u1 in [0, 1)
    return std::max(0.0, 1 + gaussian_sigma * z);
}

MaterialOptics grey_material(long id, double reflectance, std::size_t samples, double specularity,
                             Brdf brdf) {
    MaterialOptics m;
    m.id = id;
    m.name = "grey";
    m.emissivity.assign(1, std::vector<double>(samples, 1 - reflectance));
    m.fall_off.fill(1.0);
    m.specularity = specularity;
    m.brdf = std::move(brdf);
    return m;
}

}  // namespace sigchain::radiometry
