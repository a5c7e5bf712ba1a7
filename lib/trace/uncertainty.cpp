// First-order propagation of the inputs' uncertainties to the pixel radiance
// (uncertainty.hpp; White (1996), section 5.1.2; Beers (1957)).
#include "trace/uncertainty.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace sigchain::trace {
namespace {

enum Slot { kEs, kTau1, kTau2, kLus, kLds, kZenith, kGlobalSlots };

Sigma sigma_of(const io::UncRow& r) {
    return {r.relative ? r.sigma / 100 : r.sigma, r.relative};
}

// The index in `materials` of the material a row names by id or name, or -1.
long material_index(const std::string& key, const radiometry::MaterialLibrary& materials) {
    const auto& all = materials.materials();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i].name == key) return static_cast<long>(i);
    if (key.find_first_not_of("0123456789") != std::string::npos || key.size() > 9) return -1;
    const radiometry::MaterialOptics* m = materials.find(std::stol(key));
    return m ? static_cast<long>(m - all.data()) : -1;
}

// The contribution of an input to the pixel: dL/dx sigma, with `scaled` = x dL/dx
// for a relative sigma and `partial` = dL/dx for an absolute one.
double contribution(const Sigma& s, double scaled, double partial) {
    return s.relative ? s.value * scaled : s.value * partial;
}

}  // namespace

InputUncertainty resolve_uncertainty(const io::Unc& unc, const std::string& path,
                                     const radiometry::MaterialLibrary& materials) {
    InputUncertainty u;
    const std::size_t n = materials.materials().size();
    u.reflectance.assign(n, {});
    u.specularity.assign(n, {});
    for (const io::UncRow& r : unc.rows) {
        switch (r.term) {
            case io::UncTerm::SolarIrradiance: u.es = sigma_of(r); break;
            case io::UncTerm::SunTransmission: u.tau1 = sigma_of(r); break;
            case io::UncTerm::PathTransmission: u.tau2 = sigma_of(r); break;
            case io::UncTerm::UpwelledRadiance: u.lus = sigma_of(r); break;
            case io::UncTerm::SkyRadiance: u.lds = sigma_of(r); break;
            case io::UncTerm::SunZenith: u.sun_zenith_deg = r.sigma; break;
            case io::UncTerm::Reflectance:
            case io::UncTerm::Specularity: {
                const long i = material_index(r.material, materials);
                if (i < 0)
                    throw DataError({path, r.line}, "material " + quoted(r.material) +
                                                        " is not in the material file");
                auto& list = r.term == io::UncTerm::Reflectance ? u.reflectance : u.specularity;
                list[static_cast<std::size_t>(i)] = sigma_of(r);
                break;
            }
        }
    }
    return u;
}

InputUncertainty read_input_uncertainty(const std::string& path,
                                        const radiometry::MaterialLibrary& materials) {
    if (path.empty()) return resolve_uncertainty({}, path, materials);
    return resolve_uncertainty(io::read_unc_file(path), path, materials);
}

PixelUncertainty::PixelUncertainty(const InputUncertainty* u, std::size_t bands)
    : m_u(u),
      m_slots(u ? kGlobalSlots + 2 * u->reflectance.size() : 0),
      m_acc(bands * m_slots, 0.0) {}

void PixelUncertainty::clear() { std::fill(m_acc.begin(), m_acc.end(), 0.0); }

// The partials of L = tau2 (solar + downwelled + emitted) + L_us (White (1996), section
// 5.1.2's Big Equation at the primary hit): solar is linear in Es and in tau1, the
// reflected part in the hit's reflectance and in SPECULARITY, the downwelled part in L_ds.
void PixelUncertainty::add_hit(std::size_t band, const HitTerms& t) {
    const InputUncertainty& u = *m_u;
    double* a = &m_acc[band * m_slots];
    const double solar = t.tau2 * t.solar;
    a[kEs] += contribution(u.es, solar, 0.0);
    a[kTau1] += contribution(u.tau1, solar, t.tau1 > 0 ? solar / t.tau1 : 0.0);
    a[kTau2] += contribution(u.tau2, t.tau2 * t.leave, t.leave);
    a[kLus] += contribution(u.lus, t.lus, 1.0);
    a[kLds] += contribution(u.lds, t.tau2 * t.downwelled, 0.0);
    a[kZenith] += u.sun_zenith_deg * t.tau2 * t.solar_per_zenith_deg;
    if (t.material < 0) return;
    const auto m = static_cast<std::size_t>(t.material);
    const double reflected = t.tau2 * (t.solar + t.downwelled);  // r dL/dr
    a[kGlobalSlots + 2 * m] +=
        contribution(u.reflectance[m], reflected, t.r > 0 ? reflected / t.r : 0.0);
    const double per_s = t.tau2 * t.solar_per_specularity;  // dL/ds: the sun's and the sky's
    a[kGlobalSlots + 2 * m + 1] += contribution(u.specularity[m], t.specularity * per_s, per_s);
}

double PixelUncertainty::sigma(std::size_t band, long samples) const {
    const double* a = &m_acc[band * m_slots];
    double sum = 0;
    for (std::size_t i = 0; i < m_slots; ++i) {
        const double c = a[i] / static_cast<double>(samples);
        sum += c * c;
    }
    return std::sqrt(sum);
}

}  // namespace sigchain::trace
