// Published reflectance spectra, class materials mixed from them, and their .ems curves.
#include "landcover/spectra.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <set>

#include "core/data_dir.hpp"
#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/output.hpp"

namespace sigchain::landcover {

namespace {

// A spectrum named relative to the materials file's folder, else to the data directory
// (data/spectra/ holds the published ones, in the source tree and an installed copy).
std::string spectrum_path(const std::filesystem::path& folder, const std::string& name) {
    const auto local = folder / name;
    if (std::filesystem::path(name).is_absolute() || std::filesystem::exists(local))
        return local.string();
    const auto shared = std::filesystem::path(data_dir()) / name;
    return std::filesystem::exists(shared) ? shared.string() : local.string();
}

}  // namespace

double Spectrum::at(double wavelength_um) const {
    return interpolate_clamped(this->wavelength_um, reflectance, wavelength_um);
}

Spectrum parse_spectrum(const TextInput& in) {
    Spectrum s;
    s.path = in.name();
    LineCursor cursor(in);
    cursor.require_not_empty("a row 'wavelength_um reflectance'");
    while (!cursor.at_end()) {
        const auto f = cursor.fields(2, "a row 'wavelength_um reflectance'");
        const auto where = cursor.where();
        const double w = parse_double(f[0], where, "a wavelength (um)");
        const double r = parse_double(f[1], where, "a reflectance");
        if (!(w > 0)) throw DataError(where, "expected a wavelength above 0 um");
        if (!s.wavelength_um.empty() && !(w > s.wavelength_um.back()))
            throw DataError(where, "expected a wavelength above the previous row's");
        if (!(r >= 0 && r <= 1)) throw DataError(where, "expected a reflectance from 0 to 1");
        s.wavelength_um.push_back(w);
        s.reflectance.push_back(r);
    }
    return s;
}

double Material::at(double wavelength_um) const {
    double r = 0;
    for (std::size_t i = 0; i < spectra.size(); ++i) r += fractions[i] * spectra[i].at(wavelength_um);
    return r;
}

std::vector<double> Material::wavelengths_um() const {
    std::set<double> all;
    for (const auto& s : spectra) all.insert(s.wavelength_um.begin(), s.wavelength_um.end());
    return {all.begin(), all.end()};
}

std::vector<Material> read_materials(const std::string& path) {
    const auto in = TextInput::from_file(path);
    const auto folder = std::filesystem::path(path).parent_path();
    LineCursor cursor(in);
    cursor.require_not_empty("a material 'NAME FRACTION SPECTRUM ...'");
    std::vector<Material> out;
    std::set<std::string> names;
    while (!cursor.at_end()) {
        const Line& line = cursor.next("a material");
        const auto where = cursor.where(line);
        const auto f = split_fields(line.text);
        if (f.size() < 3 || (f.size() - 1) % 2 != 0)
            throw DataError(where, "expected NAME FRACTION SPECTRUM [FRACTION SPECTRUM ...]");
        Material m;
        m.name = std::string(f[0]);
        m.line = line.number;
        if (!names.insert(m.name).second)
            throw DataError(where, "material '" + m.name + "' given twice");
        double sum = 0;
        for (std::size_t i = 1; i < f.size(); i += 2) {
            const double fr = parse_double(f[i], where, "a fraction");
            if (!(fr > 0 && fr <= 1)) throw DataError(where, "expected a fraction in (0, 1]");
            sum += fr;
            const auto file = spectrum_path(folder, std::string(f[i + 1]));
            m.fractions.push_back(fr);
            m.spectra.push_back(read_spectrum(file));
        }
        if (sum > 1 + 1e-9) throw DataError(where, "the fractions add up to more than 1");
        out.push_back(std::move(m));
    }
    return out;
}

std::map<std::string, std::vector<double>> read_scales(const std::string& path,
                                                       std::size_t bands) {
    const auto in = TextInput::from_file(path);
    LineCursor cursor(in);
    std::map<std::string, std::vector<double>> out;
    while (!cursor.at_end()) {
        const auto f = cursor.fields(bands + 1, "a class name and one scale per band");
        std::vector<double> v;
        for (std::size_t b = 1; b <= bands; ++b)
            v.push_back(parse_double(f[b], cursor.where(), "a scale"));
        out[std::string(f[0])] = v;
    }
    return out;
}

std::size_t band_of(const io::Snd& snd, double wavelength_um) {
    const double nu = cm1_from_um(wavelength_um);
    std::size_t best = 0;
    double best_gap = INFINITY;
    for (std::size_t b = 0; b < snd.bands.size(); ++b) {
        const auto& band = snd.bands[b];
        const double gap = nu < band.min_wavenumber_cm1   ? band.min_wavenumber_cm1 - nu
                           : nu > band.max_wavenumber_cm1 ? nu - band.max_wavenumber_cm1
                                                          : 0.0;
        if (gap < best_gap) best_gap = gap, best = b;
    }
    return best;
}

void write_material_ems(const std::vector<Material>& materials, const io::Snd& snd,
                        const std::map<std::string, std::vector<double>>& scales,
                        const std::string& outdir, const std::string& source_note) {
    constexpr double kMarginUm = 0.05;  // rows kept beyond each band's span
    std::vector<std::unique_ptr<AtomicOutput>> files;
    for (const auto& m : materials) {
        if (!scales.empty() && !scales.count(m.name))
            throw DataError({source_note, 0}, "no scales for material '" + m.name + "'");
        files.push_back(std::make_unique<AtomicOutput>(outdir + "/" + m.name + ".ems"));
        std::ostream& out = files.back()->stream();
        out << "# " << m.name << ": emissivity = 1 - reflectance (" << source_note << ")\n";
        out << "# reflectance =";
        for (std::size_t i = 0; i < m.spectra.size(); ++i)
            out << (i ? " +" : "") << " " << m.fractions[i] << " x "
                << std::filesystem::path(m.spectra[i].path).filename().string();
        out << "\n1\n";
        for (int a = 0; a <= 90; ++a) out << "1\n";
        out << "CURVE_BEGIN\n" << std::setprecision(9);
        // The material's own wavelengths within each band's window, and the window's ends
        // (interpolated), so that every band is bracketed even by a sparse spectrum.
        std::set<double> rows;
        const auto own = m.wavelengths_um();
        for (const auto& b : snd.bands) {
            const double lo = um_from_cm1(b.max_wavenumber_cm1) - kMarginUm;
            const double hi = um_from_cm1(b.min_wavenumber_cm1) + kMarginUm;
            rows.insert({lo, hi});
            rows.insert(std::lower_bound(own.begin(), own.end(), lo),
                        std::upper_bound(own.begin(), own.end(), hi));
        }
        for (double w : rows) {
            const double s = scales.empty() ? 1.0 : scales.at(m.name)[band_of(snd, w)];
            out << w << " " << 1 - std::clamp(m.at(w) * s, 0.0, 1.0) << "\n";
        }
        out << "CURVE_END\n";
    }
    std::vector<AtomicOutput*> all;
    for (auto& f : files) all.push_back(f.get());
    commit_together(all);
}

}  // namespace sigchain::landcover
