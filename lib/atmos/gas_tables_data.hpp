// GasTables' data, shared by the implementation files of gas_absorption.hpp
// (gas_absorption.cpp, gas_terms.cpp); no other file includes it.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "atmos/gas_absorption.hpp"

namespace sigchain::atmos {

// Band-model absorbers (the first 11 gases of Gas; HNO3 is a Beer's-law term).
constexpr int kBandGases = 11;
constexpr int kFirstBandId = 17;  // LOWTRAN absorber index IW of H2O band 17

struct GasTables::Data {
    // C' on a 5 cm-1 grid from nu0 (cm-1); band = band id - 17, or -1 in a gap.
    struct BandGrid {
        int nu0_cm1 = 0;
        std::vector<double> cprime;
        std::vector<std::int8_t> band;
    };
    std::array<BandGrid, kBandGases> grids;
    std::array<double, GasColumn::kBandCount> a{}, n_p{}, m_t{};
    std::array<int, GasColumn::kBandCount> band_gas{};  // int(Gas) of each band, -1 unset
    // h2o_continuum.txt, -20..20000 cm-1 step 10 (1e-20 cm3 molecule-1 per cm-1).
    std::vector<double> h2o_self296, h2o_self260, h2o_foreign296;
    std::vector<double> n2_km;                // n2_continuum.txt, 2080..2740 step 5
    std::vector<double> o2_s0, o2_a, o2_b;    // o2_continuum_1395_1760.txt, step 5
    std::vector<double> chappuis;             // C8(1..57), (atm-cm)^-1
    std::vector<double> hh_c0, hh_c1, hh_c2;  // o3_hartley_huggins.txt, 27370.. step 5
    std::vector<double> hno3;                 // hno3_band_coefficients.txt, 850..1735 step 5
    // The wavenumbers the tables were read for (GasTables::load's range; all by default):
    // a table reaching them is read, another may be empty.
    double nu_lo = -std::numeric_limits<double>::infinity();
    double nu_hi = std::numeric_limits<double>::infinity();
    std::vector<std::string> skipped;  // files not read
};

// Throws std::logic_error unless the tables were read for nu (GasTables::load's range).
void require_loaded(const GasTables::Data& d, double nu_cm1);

}  // namespace sigchain::atmos
