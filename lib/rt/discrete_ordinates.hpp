// Plane-parallel scalar radiative transfer by the discrete-ordinate method (after
// Stamnes, Tsay, Wiscombe & Jayaweera 1988, Appl. Opt. 27, 2502: "DISORT"), written for
// sigchain: multi-layer, beam and isotropic sources at the top, Lambertian surface,
// thermal emission with Planck linear in optical depth within a layer, delta-M scaling,
// intensities at any optical depth and direction by analytic integration of the source
// function, azimuth dependence by a Fourier (cosine) series.
//
// Conventions follow DISORT's so its published test problems map one to one: optical
// depth measured from the top; mu = cosine of the polar angle of propagation, mu > 0
// travelling up, mu < 0 travelling down; phi = azimuth of propagation relative to the
// beam's (degrees); intensities exclude the direct beam; fluxes and intensities are in
// the units of the sources (beam flux normal to the beam, intensities per sr).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace sigchain::rt {

struct Layer {
    double tau = 0;            // optical depth of the layer, >= 0
    double ssa = 0;            // single-scattering albedo, [0, 1]
    std::vector<double> pmom;  // Legendre moments, pmom[0] = 1 (P = sum (2k+1) pmom[k] P_k)
};

// The layers' exact phase functions, for when their Legendre moments cannot represent
// them (a tabulated Mie function's forward peak needs thousands): `components`
// functions of the cosine of the scattering angle in the moments' normalisation
// (sum (2k+1) pmom_k P_k, i.e. 4 pi times the phase function in sr-1, average 1 over
// the sphere), and per layer the weights of its mixture (summing to 1 where it
// scatters). The layers' pmom must still hold the moments of the same mixture (the
// solver's delta-M truncation and the IMS correction use them). `evaluate` is called
// from the solving thread only.
struct ExactPhase {
    std::size_t components = 0;  // 0: the moments are the phase function
    // Writes every component's value at cos_scat (in [-1, 1]) into out[0 .. components).
    std::function<void(double cos_scat, double* out)> evaluate;
    // Optional: every component's mean over the n cosines cos_scat[0 .. n) into
    // out[0 .. components), each the sum over k in order of evaluate(cos_scat[k]) / n:
    // the same numbers as n calls of evaluate, for a phase function that can keep the
    // work that depends on the cosines alone (the TMS correction's azimuthal means ask
    // the same cosines in every solve with the same sun and directions).
    std::function<void(const double* cos_scat, int n, double* out)> mean;
    std::vector<double> weights;  // [layer * components + c]
};

struct Problem {
    std::vector<Layer> layers;         // top to bottom, at least one
    int streams = 16;                  // even, >= 4 (N in DISORT; N/2 per hemisphere)
    bool delta_m = true;               // delta-M scaling of peaked phase functions
    bool intensity_correction = true;  // Nakajima-Tanaka TMS correction with delta-M
    // Nakajima-Tanaka IMS correction (with intensity_correction): the secondary
    // scattering within the forward peak, for downward directions within 10 deg of the
    // beam's zenith angle (the aureole). Off by default so that weakly peaked problems
    // (Henyey-Greenstein aerosols) keep their results.
    bool secondary_correction = false;
    ExactPhase exact_phase;  // used by the TMS correction when components > 0

    double beam_flux = 0;      // incident beam flux normal to its direction, >= 0
    double beam_mu0 = 1;       // cosine of the beam's zenith angle, (0, 1]
    double beam_phi0_deg = 0;  // azimuth of the beam
    // Pseudo-spherical beam (DISORT's / libRadtran's "pseudospherical"; Dahlback &
    // Stamnes 1991, Planet. Space Sci. 39, 671): per layer, top first, the beam's slant
    // optical path over the layer's vertical optical depth (its Chapman factor), > 0;
    // the beam at a layer's top is then beam_flux exp(-sum above of factor * tau) and
    // decays as exp(-factor t) within it, while scattering keeps the angle beam_mu0.
    // Empty: 1 / beam_mu0 in every layer (plane-parallel).
    std::vector<double> beam_airmass;
    double top_isotropic = 0;  // isotropic intensity incident at the top, >= 0
    double albedo = 0;         // Lambertian surface albedo, [0, 1]

    // Thermal emission (empty: none): Planck radiance (intensity units) at each level
    // boundary, top first, layers.size() + 1 values; linear in optical depth within a
    // layer, emitted with weight (1 - ssa).
    std::vector<double> planck_levels;
    double planck_surface = 0;  // B(T_surface): the surface emits (1 - albedo) * this
    double top_emission = 0;    // emissivity * B(T_top) incident at the top (DISORT temis*ttemp)

    // Where and in which directions results are wanted.
    std::vector<double> utau;     // optical depths (unscaled, from the top), ascending
    std::vector<double> umu;      // cosines, nonzero, ascending
    std::vector<double> phi_deg;  // azimuths
    // Per utau (empty: both directions at every depth): the intensities wanted there,
    // upward (mu > 0), downward (mu < 0), both or none. The others come out 0 and cost
    // nothing: a layer no wanted intensity depends on is not integrated (the upward
    // radiance at a sensor needs only the layers below it, the sky at the ground every
    // layer above), and the intensity corrections skip them. Fluxes are always computed.
    enum Want : unsigned char { kWantNone = 0, kWantUp = 1, kWantDown = 2, kWantBoth = 3 };
    std::vector<unsigned char> want;

    // Azimuthal (Fourier) series convergence: stop after two successive modes whose
    // contribution to every intensity is below this fraction of the intensity (DISORT's
    // ACCUR). 0 computes all modes m = 0 .. streams - 1.
    double azimuth_accuracy = 1e-5;
    // Every intensity is its mean over azimuth (the same at every phi_deg): Fourier mode 0
    // only (the modes m > 0 integrate to 0 over a full circle), and the TMS and IMS
    // corrections averaged over azimuth. Exact for what is read as such: mu = +-1
    // (P_l^m(+-1) = 0 for m > 0, so every mode's sum there is mode 0) and rings of
    // directions spanning every azimuth; about one Fourier mode's cost instead of N.
    bool azimuth_mean = false;
};

struct LevelResult {
    double direct_down = 0;     // direct-beam flux (horizontal surface)
    double diffuse_down = 0;    // diffuse downward flux
    double diffuse_up = 0;      // diffuse upward flux
    double dfdt = 0;            // d(net flux)/d(tau), DISORT's: (1 - ssa) 4 pi (mean
                                // intensity incl. beam - B); > 0 where absorption wins
    double mean_intensity = 0;  // diffuse mean intensity (average over 4 pi)
    // Diffuse intensity at umu[i], phi_deg[j]: intensity[i * phi_deg.size() + j].
    std::vector<double> intensity;
};

struct Result {
    std::vector<LevelResult> levels;  // one per utau
};

// Solves the problem. Throws sigchain::Error on invalid input (with what is wrong):
// no layers, streams odd or outside 4..128, tau < 0, ssa outside [0, 1], pmom[0] != 1
// for a scattering layer, mu0 outside (0, 1] with a beam, beam_airmass not one positive
// value per layer (when given), planck_levels of the wrong
// size, utau not ascending within [0, total tau], a zero or |umu| > 1 cosine.
// exact_phase with other than `components` weights per layer or no function, want not
// one value of 0-3 per utau (when given).
// Method notes: single-scattering albedo 1 is computed as 1 - 1e-9 (DISORT's dither);
// with delta_m and intensity_correction the Nakajima-Tanaka (1988, JQSRT 40, 51) TMS
// correction is applied (eq. 13: the beam's single scattering with the exact phase
// function, the moments' or exact_phase's), and with secondary_correction also their
// IMS term (eqs. 14-15, in DISORT's form: Stamnes et al. 2000, DISORT report v1.1,
// eqs. A7-A13), which matters within a few degrees of the beam direction for strongly
// peaked phase functions. Reentrant: concurrent calls
// share nothing (a thread keeps its last solve's mode 0 for its next solve of
// the same layers without sources, bit for bit what solving it again gives). Cost for
// 35 layers, 16 streams, 110 umu, 40 azimuths: ~8 ms of one core (bench/bench_rt: 2.1 /
// 8.0 / 52 ms for 8 / 16 / 32 streams).
Result solve(const Problem& problem);

}  // namespace sigchain::rt
