// trace --uncertainty: the per-pixel standard uncertainty of the radiance at the sensor
// from the one-sigma uncertainties of the render's inputs (unc(5)), by first-order
// propagation through the Big Equation (White (1996), section 5.1.2; Beers (1957)):
// sigma_L^2 = sum_i (dL/dx_i sigma_i)^2 over independent inputs x_i. The partials are
// those of each primary hit's terms, accumulated alongside the radiance (trace(1)
// UNCERTAINTY). Radiance in W cm-2 sr-1 um-1.
#pragma once

#include <string>
#include <vector>

#include "io/unc.hpp"
#include "radiometry/material.hpp"

namespace sigchain::trace {

// One input's one-sigma uncertainty: `value` in the input's unit, or a fraction of the
// input (not per cent) when `relative`; 0: none.
struct Sigma {
    double value = 0;
    bool relative = false;
    bool any() const { return value > 0; }
};

// A .unc resolved against the render's materials.
struct InputUncertainty {
    Sigma es, tau1, tau2, lus, lds;
    double sun_zenith_deg = 0;  // absolute, degrees
    // Per material of MaterialLibrary::materials() (same order): reflectance 1 - eps and
    // SPECULARITY.
    std::vector<Sigma> reflectance, specularity;
};

// Resolves each row's material by MATERIAL_ID (an integer) or MATERIAL_NAME. Throws
// DataError at the row's line ("FILE:LINE: ...") for a material the .mat lacks.
InputUncertainty resolve_uncertainty(const io::Unc& unc, const std::string& path,
                                     const radiometry::MaterialLibrary& materials);

// What one primary hit gives the propagation at one band-centre sample: the terms of
// its radiance at the sensor, L = tau2 (solar + downwelled + emitted) + L_us.
struct HitTerms {
    double tau2 = 0, lus = 0;
    double leave = 0;       // radiance leaving the hit toward the sensor
    double solar = 0;       // rho E_s tau1 cos(sigma)/pi F V (the Big Equation's solar part)
    double downwelled = 0;  // rho times the sky and neighbours' irradiance term
    double solar_per_zenith_deg = 0;  // d(solar)/d(sun zenith), per degree
    // d(solar + downwelled)/d(SPECULARITY): the sun's and the sky's (and neighbours')
    // parts both, though the name says solar (HitTruth's, which render.cpp copies).
    double solar_per_specularity = 0;
    double tau1 = 1;                  // sun to ground transmittance at the sample
    double r = 0;                     // the hit material's 1 - eps at the sample
    double specularity = 0;           // the hit material's SPECULARITY
    long material = -1;               // index into InputUncertainty::reflectance
};

// The uncertainties of the .unc at `path` resolved against `materials`; none (every
// sigma 0) for an empty path. Throws IoError/DataError naming the file and line.
InputUncertainty read_input_uncertainty(const std::string& path,
                                        const radiometry::MaterialLibrary& materials);

// One worker's accumulator of a pixel's partials times sigmas, per band: each input's
// contributions summed over the pixel's samples before squaring (one input, fully
// correlated across the samples), the inputs summed in quadrature.
class PixelUncertainty {
public:
    PixelUncertainty() = default;
    PixelUncertainty(const InputUncertainty* u, std::size_t bands);
    bool active() const { return m_u != nullptr; }
    void clear();
    void add_hit(std::size_t band, const HitTerms& t);
    // The standard uncertainty of the pixel's mean over `samples` primary samples.
    double sigma(std::size_t band, long samples) const;

private:
    const InputUncertainty* m_u = nullptr;
    std::size_t m_slots = 0;  // per band: 6 global inputs, then 2 per material
    std::vector<double> m_acc;
};

}  // namespace sigchain::trace
