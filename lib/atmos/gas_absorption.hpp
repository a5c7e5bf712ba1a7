// Molecular absorption by LOWTRAN 7's band model (Pierluissi & Maragoudakis double
// exponential, 20 cm-1 resolution on a 5 cm-1 grid) for H2O, O3, CO2, CO, CH4, N2O, O2
// and the minor gases, plus the H2O, N2 and O2 continua and the ozone ultraviolet and
// visible cross sections, from data/atmosphere/lowtran7/.
//
// What is modelled (every formula from the '#' headers of the tables, which describe
// LOWTRAN 7's subroutines TRANS, STDMDL, C4DTA, C8DTA, O3INT, O2CONT, HNO3, SINT):
//   - band model, per absorber: T = exp(-(10^C'(nu) * W)^a), W = sum over the path of
//     rho ds (P/1013.25)^n (273.15/T)^m with the band's n, m (H2O in g cm-2, the other
//     ten gases in atm-cm); T = 1 where a*(log10 W + C') <= -6 or nu is outside the
//     absorber's tables. LOWTRAN sets T = 0 where that exponent is >= 2; here the
//     formula is kept there too (T < 4e-44), so -ln T stays finite for the solver.
//     C' is taken at the 5 cm-1 grid point nearest nu (LOWTRAN only steps in 5 cm-1);
//     so are the other 5 cm-1 tables (N2, O2, HNO3, Hartley-Huggins), while the H2O
//     continuum (10 cm-1) and Chappuis (200 cm-1) tables are interpolated linearly.
//   - Beer's-law terms: H2O self and foreign continuum (CKD, radiation term, 296/260 K
//     self interpolation, far-wing FUDGE; nu < 20000 cm-1), N2 continuum
//     (2080-2740 cm-1), O2 collision band (1395-1760 cm-1), HNO3 (three bands), ozone
//     Chappuis (13000-24200 cm-1) and Hartley-Huggins with its quadratic temperature
//     dependence (27370-40800 cm-1); none of ozone between 24370 and 27370 cm-1, as in
//     LOWTRAN 7. Not included (outside 0.28-28 um): O2 Herzberg (> 36000 cm-1), ozone
//     Molina UV (>= 40800 cm-1), O2 Schumann-Runge.
//   - layer amounts: every scaled amount's integrand is evaluated on the levels and
//     integrated over each layer assuming exponential variation between levels (as
//     LOWTRAN's exponential density interpolation); temperature-weighted continuum sums
//     use the layer's mean temperature.
//
// Equivalent Beer's law (layer_absorption_depth): a scattering solver needs an optical
// depth per layer, but band-model transmittances do not multiply (T(W1 + W2) is not
// T(W1) T(W2)). Each layer gets tau_k = -ln T(top..k) + ln T(top..k+1) for the band
// model (vertical paths from the top of the profile), plus the continua. The vertical
// transmittance from the top to any level is then exact; slant and partial paths in
// that Beer's-law medium are approximate. Direct-beam and line-of-sight paths must use
// transmittance(), which applies the band model to the path's summed amounts exactly;
// only the diffuse field uses the equivalent depths, and where a gas is too strong for
// them the strongest one (and a second that overlaps it strongly) is carried as an
// exponential sum instead (absorption_terms in gas_terms.cpp, exp_sum.hpp).
//
// Thread-safety: both classes are immutable after construction; const use from several
// threads is safe. GasTables copies share their data; GasColumn keeps its tables alive.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "atmos/profile.hpp"

namespace sigchain::atmos {

// The tables, loaded once.
class GasTables {
public:
    // Throws DataError naming the file and line of a bad table. With a wavenumber range
    // (cm-1), only the tables that reach within kLoadMargin of it are read (a band
    // model's grid when one of its bands' ranges in band_model_constants.txt does, a
    // continuum or cross-section table by its fixed grid), and GasColumn then answers for
    // wavenumbers in that range only (std::logic_error beyond).
    static GasTables load(const std::string& data_dir);
    static GasTables load(const std::string& data_dir, double nu_lo_cm1, double nu_hi_cm1);
    static constexpr double kLoadMargin = 100;  // cm-1, beyond any table's interpolation
    // The files a ranged load did not read (names without the directory), in file order.
    const std::vector<std::string>& skipped() const;
    // (implementation-defined members follow)

    // data_dir is the repository's data/ folder: the tables are read from
    // DATA_DIR/atmosphere/lowtran7/. IoError when a file cannot be read.
    struct Data;

private:
    explicit GasTables(std::shared_ptr<const Data> data) : m_data(std::move(data)) {}
    std::shared_ptr<const Data> m_data;
    friend class GasColumn;
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
    // The same along a slant path whose amounts are air_mass[k] times layer k's
    // vertical amounts (the band model applied to the summed slant amounts; the
    // layers' air masses from spherical_path.hpp, weighted by air density).
    double transmittance_along(double nu_cm1, std::size_t level_i, std::size_t level_j,
                               const std::vector<double>& air_mass) const;

    // Absorption optical depth of each layer [level k, level k+1] (profile.size() - 1
    // values) for a scattering solver that needs Beer's law: the vertical band-model
    // transmittance of the path from the top of the profile down to each level,
    // differenced in -ln T, plus the continua (documented in the implementation).
    std::vector<double> layer_absorption_depth(double nu_cm1) const;

    // Exponential-sum (k-distribution) absorption at nu for a scattering solver
    // (exp_sum.hpp). A gas so weak that path_factor (C W_column)^a <= -ln(1 - tol) is
    // within tol of Beer's law on every path of at most path_factor columns. Of the
    // others, the strongest (largest -ln T over path_factor columns) has its band model
    // exp(-(C W)^a) fitted by a sum of exponentials in its scaled amount W over the path
    // amounts of this column, from the thinnest layer's vertical amount to path_factor
    // times the vertical column, within tol (transmittance) with at most max_terms
    // terms; a term's k applies to every layer's amount (correlated-k). Every other gas
    // keeps its equivalent depth of layer_absorption_depth, as do the continua (Beer's
    // law), the same in every term; except a second gas that overlaps the first
    // strongly: one whose equivalent depths err by more than tol / 2 on the paths from
    // a level to the top at up to path_factor air masses (the most erring such gas).
    // Then both gases are fitted within tol / 3 and their sums multiplied (the band
    // model's transmittances multiply; a pair of terms is one term, its depths the sum
    // of both), the lightest pairs, together at most tol / 3 of the weight, merged into
    // the nearest kept pair: within tol of the band model's product on any path of at
    // most path_factor columns, for the two gases. With no gas to fit (or max_terms 1)
    // the one term is layer_absorption_depth itself, weight 1, `equivalent` true.
    // pairs_allowed false: never a second gas.
    struct Terms {
        std::vector<double> weight;                     // sum 1
        std::vector<std::vector<double>> depth;         // [term][layer], bottom first
        bool equivalent = true;                         // the one term is layer_absorption_depth
        int gas = -1;                                   // the fitted gas (int(Gas)), -1: none
        int gas2 = -1;                                  // the second, overlapping, or -1
        std::vector<std::vector<double>> fitted_depth;  // [term][layer]: their part of depth
    };
    Terms absorption_terms(double nu_cm1, double path_factor, double tol, int max_terms,
                           bool pairs_allowed = true) const;

    // Equivalent depths of every layer (bottom first) of all gases but band-model gases
    // `exclude` and `exclude2` (-1: none) and the continua, exact on vertical paths from
    // level `pivot` (ColumnModel::gas_depths_from says why): the others' part of a
    // term's depths for the emission toward the ground or the sensor.
    std::vector<double> depths_from(double nu_cm1, std::size_t pivot, int exclude,
                                    int exclude2 = -1) const;

    // (implementation-defined members follow)

    // Components of transmittance() (same arguments; i == j gives 1 / 0; the level
    // order does not matter). Band-model transmittance of one absorber (HNO3, which
    // LOWTRAN treats by Beer's law, is in continuum_optical_depth instead):
    double band_transmittance(Gas gas, double nu_cm1, std::size_t level_i, std::size_t level_j,
                              double mu) const;
    // Optical depth of every Beer's-law term (continua, ozone UV/visible, HNO3):
    double continuum_optical_depth(double nu_cm1, std::size_t level_i, std::size_t level_j,
                                   double mu) const;
    std::size_t size() const { return m_levels; }

    // Scaled-amount quantities accumulated from the bottom level: the 41 bands of
    // band_model_constants.txt (LOWTRAN band ids 17-57), then the Beer's-law amounts.
    static constexpr int kBandCount = 41;
    static constexpr int kQuantityCount = kBandCount + 11;

private:
    struct FitBand {            // a gas's band at one nu (gas_terms.cpp)
        int band = -1;          // -1: no band there
        double c = 0;           // 10^C'
        std::vector<double> w;  // scaled amount W of every layer, bottom first
        double column = 0;      // W of the whole column
    };
    FitBand fit_band(int gas_index, double nu_cm1) const;
    double equivalent_error(int gas_index, double nu_cm1, double path_factor) const;
    void add_equivalent_band_depth(int gas_index, double nu_cm1, std::vector<double>& tau) const;
    void add_continuum_depth(double nu_cm1, std::vector<double>& tau) const;
    double band_optical_depth(int gas_index, double nu_cm1, std::size_t lo, std::size_t hi,
                              double mu) const;
    double band_depth_of_amount(int band, double cprime, double w) const;
    double amount(int quantity, std::size_t lo, std::size_t hi) const {
        return m_cumulative[hi * kQuantityCount + quantity] -
               m_cumulative[lo * kQuantityCount + quantity];
    }

    std::shared_ptr<const GasTables::Data> m_tables;
    std::size_t m_levels = 0;
    // m_cumulative[level * kQuantityCount + q]: amount q from the bottom to the level.
    std::vector<double> m_cumulative;
};

}  // namespace sigchain::atmos
