// Molecular absorption by LOWTRAN 7's band model (Pierluissi & Maragoudakis double
// exponential, 20 cm-1 resolution on a 5 cm-1 grid) for H2O, O3, CO2, CO, CH4, N2O, O2
// and the minor gases, plus the H2O, N2 and O2 continua and the ozone ultraviolet and
// visible cross sections, from data/atmosphere/lowtran7/.
#pragma once

#include <string>
#include <vector>

#include "atmos/profile.hpp"

namespace sigchain::atmos {

// The tables, loaded once.
class GasTables {
public:
    // Throws DataError naming the file and line of a bad table.
    static GasTables load(const std::string& data_dir);
    // (implementation-defined members follow)
};

// A profile's absorber amounts precomputed on its levels, for fast queries at many
// wavenumbers. Paths are straight and plane-parallel: a path through a layer at cosine
// of zenith mu holds the layer's vertical amount / mu (no refraction, no curvature).
class GasColumn {
public:
    GasColumn(const GasTables& tables, const Profile& profile);

    // Mean transmittance over LOWTRAN's 20 cm-1 interval at wavenumber nu (cm-1) of
    // all gases and continua along the path between levels i < j of the profile at
    // cosine of zenith mu (0 < mu <= 1): band model per absorber on the path's total
    // amounts, times exp(-continuum and cross-section optical depth).
    double transmittance(double nu_cm1, std::size_t level_i, std::size_t level_j, double mu) const;

    // Absorption optical depth of each layer [level k, level k+1] (profile.size() - 1
    // values) for a scattering solver that needs Beer's law: the vertical band-model
    // transmittance of the path from the top of the profile down to each level,
    // differenced in -ln T, plus the continua (documented in the implementation).
    std::vector<double> layer_absorption_depth(double nu_cm1) const;

    // (implementation-defined members follow)
};

}  // namespace sigchain::atmos
