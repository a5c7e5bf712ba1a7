// Reflectance spectra of published libraries (the ECOSTRESS files of data/spectra/),
// the class materials made of them (materials(5): linear mixtures with a shade part),
// and the .ems curves trace reads, scaled per band when a fit gives scales.
// Thread-safety: value types; free functions.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/snd.hpp"

namespace sigchain::landcover {

// A reflectance spectrum: strictly increasing wavelengths (um), reflectance in [0, 1].
struct Spectrum {
    std::vector<double> wavelength_um;
    std::vector<double> reflectance;
    std::string path;
    // Linear between rows; outside the range, the nearest end (as ems(5) interpolates).
    double at(double wavelength_um) const;
};

// Reads "wavelength_um reflectance" rows ('#' comments). Throws DataError at the line
// of a bad row, a wavelength not above the previous, or a reflectance outside [0, 1].
Spectrum parse_spectrum(const TextInput& in);
inline Spectrum read_spectrum(const std::string& path) {
    return parse_spectrum(TextInput::from_file(path));
}

// A class material: sum of fraction_i x spectrum_i; 1 - sum(fraction_i) is shade
// (reflectance 0), the linear spectral mixture of a sunlit surface and its shadows
// (Adams, Smith and Johnson (1986), J. Geophys. Res. 91(B8), 8098-8112).
struct Material {
    std::string name;
    std::vector<double> fractions;
    std::vector<Spectrum> spectra;
    int line = 0;
    double at(double wavelength_um) const;
    // Every wavelength of its spectra, sorted, without repeats.
    std::vector<double> wavelengths_um() const;
};

// materials(5): lines "NAME FRACTION SPECTRUM [FRACTION SPECTRUM ...]"; SPECTRUM paths
// relative to the materials file's folder, else to the data directory (data_dir():
// "spectra/ecostress_grass.txt" finds the published spectra wherever the scene folder
// is). Fractions in (0, 1], their sum at most 1.
std::vector<Material> read_materials(const std::string& path);

// Per-band scales of each class: "NAME s1 s2 ... sN" rows ('#' comments), N the number
// of bands of the .snd they go with.
std::map<std::string, std::vector<double>> read_scales(const std::string& path, std::size_t bands);

// Band of a wavelength for the scales: the band whose wavenumber span holds it, else the
// nearest span's (so a curve is scaled piecewise, each piece by one band's scale).
std::size_t band_of(const io::Snd& snd, double wavelength_um);

// Writes OUTDIR/NAME.ems for every material: one curve, emissivity 1 - reflectance x
// scale(band) at the material's own wavelengths within 0.05 um of the .snd's bands and
// at those windows' ends,
// no fall-off (91 ones). Without scales (empty map) every scale is 1; a class missing
// from a non-empty map is an error. Reflectance x scale is clamped to [0, 1].
void write_material_ems(const std::vector<Material>& materials, const io::Snd& snd,
                        const std::map<std::string, std::vector<double>>& scales,
                        const std::string& outdir, const std::string& source_note);

}  // namespace sigchain::landcover
