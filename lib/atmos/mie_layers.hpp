// IPH 2 in build_radiance's solver: each layer's phase function as the mixture, by
// scattering optical depth, of Rayleigh, LOWTRAN 7's Mie functions (one per aerosol
// region; mie_phase.*) and Henyey-Greenstein (cloud, and aerosol without a Mie
// function): its Legendre moments for the solver's delta-M truncation (Wiscombe 1977,
// J. Atmos. Sci. 34, 1408) and the exact mixture for the Nakajima & Tanaka (1988, JQSRT
// 40, 51) TMS correction and for single scattering. Used by lib/atmos_table's spectral samples.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "atmos/column_model.hpp"
#include "atmos/mie_phase.hpp"
#include "rt/discrete_ordinates.hpp"

namespace sigchain::atmos {

// The aerosol regions' Mie functions at one wavelength.
struct MieOptics {
    std::array<bool, 4> has{};                // region has a Mie function here
    std::array<std::vector<double>, 4> chi;   // its moments chi_0 .. chi_nmom (chi_0 = 1)
    std::array<std::vector<double>, 4> grid;  // 4 pi P / int P on phase_grid (mie_phase.hpp)
};

// The Mie functions of `column`'s regions at a wavelength, with nmom moments
// (phase_moments of the table as PHASEF interpolates it, renormalised).
MieOptics mie_optics(const ColumnModel& column, double wavelength_um, int nmom);
// The same from the regions' functions (none: no Mie function there).
MieOptics mie_optics(const std::array<std::optional<TabulatedPhase>, 4>& regions, int nmom);

// The solver's layers (top first) for the column `col` (bottom first) merged between
// the `kept` levels (ascending) as radiance_sample's merged_layers merges them: optical
// depths add, each component's scattering optical depth adds; pmom (moments + 1 values)
// and, when `exact` is given, the exact phase functions (rt::ExactPhase) of the mixture.
std::vector<rt::Layer> mie_solver_layers(const std::vector<LayerOptics>& col,
                                         const std::vector<std::size_t>& kept, const MieOptics& mie,
                                         int moments, rt::ExactPhase* exact);

}  // namespace sigchain::atmos
