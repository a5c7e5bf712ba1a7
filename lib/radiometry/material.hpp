// Materials as trace uses them: each .mat entry with its .ems (and .ext) curves
// sampled on the render's spectral grid, its angular fall-off and its specular lobe.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "io/ems.hpp"
#include "io/mat.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/spectral.hpp"

namespace sigchain::radiometry {

// A DIRSIG texture map (TEXTURE_FILE; White (1996), section 5.2.5.3): a raster whose cell values are
// .ems curve numbers, laid over the scene by the raster's geotransform, which maps
// (column, row) to scene x (east) and y (north) in scene units (mat(5)).
struct TextureMap {
    std::string file;
    long rows = 0, columns = 0;
    std::array<double, 6> geotransform{};  // GDAL order: x0, dx/dcol, dx/drow, y0, dy/dcol, dy/drow
    std::vector<std::uint16_t> curve;      // rows * columns, row-major
    // The curve number at scene point (x, y), or -1 outside the raster.
    int curve_at(double x, double y) const;
};

// The diffuse and specular parts of a material's weight w (brdf.hpp) for one viewer,
// kept apart for a material whose two parts reflect differently
// (MaterialOptics::split_reflectance): w = diffuse cos(theta_i)/pi + specular lobe/m.
struct ReflectanceSplit {
    double diffuse = 0;           // 1 - SPECULARITY
    double specular = 0;          // SPECULARITY, or the cone's depth albedo a_s (brdf.hpp)
    double lobe_probability = 0;  // chance of drawing a ray from the lobe (montecarlo, paths)
    bool lobe = false;            // a finite lobe of weight > 0
    bool delta = false;           // a mirror lobe of weight > 0
};

struct MaterialOptics {
    long id = 0;
    std::string name;
    std::string mat_file;  // for messages: "FILE:LINE: material 'NAME' (ID): ..."
    int line = 0;
    int texture_line = 0;  // TEXTURE_FILE's line (0: the entry's), for the texture's errors

    // emissivity[c][k]: curve c of the .ems at grid sample k (curve 0 is the
    // material's own; further curves are texture curves).
    std::vector<std::vector<double>> emissivity;
    std::array<double, io::kFallOffCount> fall_off{};  // F(theta) at 0..90 deg
    // Projected-solid-angle mean of F over the hemisphere, 2 Int F cos sin d(theta)
    // (set by MaterialLibrary::load/from_optics; 1 for a flat fall-off).
    double mean_fall_off = 1;
    bool flat_fall_off = true;  // F = 1 at every angle: no lookups
    double specularity = 0;                            // 0 for lambertian
    Brdf brdf;                                         // angular shape (brdf.hpp)
    // SPECULAR_CURVE: the emissivity curve whose 1 - eps is the specular reflectance
    // (mat(5)); -1: the diffuse curve's. Texture maps never change it.
    int specular_curve = -1;

    bool transmissive = false;              // UNIFORM/NONUNIFORM_TRANSMISSION
    std::vector<double> extinction_per_km;  // per grid sample (curve 0 of the .ext)
    double thickness_cm = 0;                // THICKNESS (a facet's own overrides)
    // DOUBLE_SIDED (absent: true): a single-sided facet seen from behind is black
    // (mat(5) SIDES).
    bool double_sided = true;
    // USE_GAUSSIAN_TEXTURE: the reflectance times a per-facet Gaussian gain of mean 1
    // and standard deviation gaussian_sigma (mat(5) GAUSSIAN TEXTURE).
    bool gaussian_texture = false;
    double gaussian_sigma = 0;
    std::shared_ptr<const TextureMap> texture;  // TEXTURE_FILE, or null

    // The .ems curve at scene point (x, y): the texture map's where it covers the
    // point, else `facet_curve` (the facet's own, from land use; 0 by default).
    int curve_at(double x, double y, int facet_curve) const {
        if (!texture) return facet_curve;
        int c = texture->curve_at(x, y);
        return c < 0 ? facet_curve : c;
    }

    // True when the specular part has its own reflectance: a SPECULAR_CURVE, or a cone
    // whose .ems lobe table has a depth column (White (1996), section 5.1.2's separate
    // r_specular and r_diffuse). trace then shades the two parts apart; every other
    // material keeps the single reflectance rho of reflectance().
    bool split_reflectance() const { return specular_curve >= 0 || brdf.has_depth(); }
    // The weights of the two parts for a viewer at cos_theta_o from the normal: diffuse
    // 1 - s; specular s, or with a depth column the cone's a_s(theta_o) whatever s; the
    // lobe is drawn with probability s, or a_s / (a_s + 1 - s) with a depth column.
    ReflectanceSplit split_weights(double cos_theta_o) const;

    // Fall-off as White (1996), section 5.2.3 proposes (ems(5) FALL-OFF): F lowers the
    // reflectance at high view angles, rho(lambda, theta_o) = (1 - eps(lambda)) F(theta_o),
    // and damps the radiance arriving at high zenith angles, each incoming direction
    // weighted F(theta_i). F at the angle whose cosine to the normal is `cos_theta`
    // (1 for a flat fall-off).
    double fall_off_cos(double cos_theta) const;
    // Directional emissivity of curve `curve` at `theta_deg` from the normal, by
    // Kirchhoff 1 - the directional-hemispherical reflectance:
    // 1 - (1 - eps) F(theta) [(1 - s) Fbar + s F(theta)], the lobe taken about the
    // mirror direction (at theta from the normal), Fbar = mean_fall_off; for a split
    // material 1 - F(theta) [(1 - s) r_d Fbar + w_s r_s F(theta)] with r_d = 1 - eps,
    // w_s and r_s those of split_weights and specular_reflectance. Into `out`.
    void directional_emissivity(int curve, double theta_deg, std::span<double> out) const;
    // Reflectance rho(lambda, theta) = (1 - eps(lambda)) F(theta) of an opaque facet;
    // for a transmissive one (1 - eps) F (1 - t) with t the slab transmittance at that
    // angle (mat(5): r + a + t = 1). For a split material the reflectance a uniform
    // sky sees, (1 - s) rho_d + w_s rho_s. Into `out`.
    void reflectance(int curve, double theta_deg, double thickness_cm, std::span<double> out) const;
    // rho_d: the reflectance above of curve `curve` alone (the diffuse part's).
    void diffuse_reflectance(int curve, double theta_deg, double thickness_cm,
                             std::span<double> out) const;
    // rho_s of the specular part: (1 - eps_k) F(theta) [(1 - t)] with k =
    // specular_curve, or F(theta) [(1 - t)] (grey) with a depth column, whose energy
    // is in w_s; rho_d of curve 0 for any other material.
    void specular_reflectance(double theta_deg, double thickness_cm, std::span<double> out) const;
    // Slab transmittance exp(-k d / |cos theta|) per grid sample (ext(5)), d in cm.
    void transmittance(double cos_theta, double thickness_cm, std::span<double> out) const;
    // The Gaussian texture gain of the facet with this key (any two integers naming it,
    // such as placement and facet index) for render seed `seed`: max(0, 1 + sigma z),
    // z standard normal from a hash of (seed, key) (reproducible, thread-independent);
    // 1 when the texture is off.
    double texture_gain(std::uint64_t seed, std::uint64_t key1, std::uint64_t key2) const;
};

// Reads a texture map with GDAL (band 1, any format GDAL reads). Every cell must be a
// curve number of `m`'s .ems (0 .. curves - 1) and the raster must be georeferenced
// (a geotransform); else DataError at `m`'s .mat line naming the file.
std::shared_ptr<const TextureMap> read_texture_map(const std::string& path,
                                                   const MaterialOptics& m);

class MaterialLibrary {
public:
    // Reads every .ems (and .ext) the .mat names, resolved against the .mat's
    // directory, and samples them on `grid`. Throws IoError/DataError naming the .mat
    // line of the entry whose file is missing or bad ("FILE:LINE: material 'N' (ID):
    // cannot read EMS_FILE: why").
    static MaterialLibrary load(const io::Mat& mat, const std::string& mat_path,
                                const SpectralGrid& grid);
    // Builds optics directly (tests, generated scenes): one material per entry.
    static MaterialLibrary from_optics(std::vector<MaterialOptics> materials);

    // The material with this MATERIAL_ID, or nullptr. Constant time.
    const MaterialOptics* find(long id) const;
    const std::vector<MaterialOptics>& materials() const { return m_materials; }

private:
    std::vector<MaterialOptics> m_materials;
    std::vector<int> m_index;  // id -> index into m_materials, -1 when absent
};

// A grey Lambertian (or lobed) material for tests: constant emissivity 1 - rho on a
// grid of `samples` samples, fall-off 1 everywhere.
MaterialOptics grey_material(long id, double reflectance, std::size_t samples,
                             double specularity = 0, Brdf brdf = Brdf::lambertian());

}  // namespace sigchain::radiometry
