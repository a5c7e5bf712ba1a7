// The atmospheric column of build_radiance: profile levels between the ground and the
// top (the sensor always a level), with the Rayleigh, aerosol and gas optical depths of
// every layer at a wavenumber. Units: wavenumber cm-1, altitude km.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <tuple>
#include <vector>

#include "atmos/aerosol.hpp"
#include "atmos/cirrus.hpp"
#include "atmos/cloud.hpp"
#include "atmos/column_options.hpp"
#include "atmos/gas_absorption.hpp"
#include "atmos/mie_phase.hpp"
#include "atmos/profile.hpp"
#include "atmos/rain.hpp"
#include "atmos/spherical_path.hpp"
#include "io/cdk.hpp"

namespace sigchain::atmos {

// Whether the deck's aerosols scatter by LOWTRAN 7's Mie phase functions: IPH 2 with
// IEMSCT 2, and IEMSCT 1, whose deck has no CARD 3A1 to override the models' own
// functions (IPH 0 and 1 are the user's; man build_radiance(1), DECK FIELDS).
bool deck_mie_phase(const io::CdkCard1& card1, const io::CdkGeometry& geometry);

// The optical properties of one layer at one wavenumber.
struct LayerOptics {
    double tau_rayleigh = 0;
    double tau_aerosol = 0;  // extinction (aerosols, water cloud, rain and cirrus: CARD 2 ICLD)
    double ssa_aerosol = 0;
    double g_aerosol = 0;
    double tau_gas = 0;  // equivalent Beer's-law absorption (GasColumn)
    // IPH 2 (ColumnModel::mie()): the scattering optical depth of each aerosol region
    // (AerosolModel's four) that has a Mie phase function at this wavenumber; the rest
    // of the aerosol and cloud scattering, tau_aerosol ssa_aerosol - their sum, goes by
    // Henyey-Greenstein with g_other. All 0 without IPH 2.
    std::array<double, 4> tau_scat_mie{};
    double g_other = 0;
};

// The column between the ground and the top: levels, aerosols, cloud, rain, cirrus and
// gases. Const methods may be called from several threads at once.
class ColumnModel {
public:
    // Throws DataError when the sensor does not lie above the ground.
    ColumnModel(const io::CdkRun& run, double sensor_km, const ColumnOptions& options);
    ColumnModel(const ColumnModel&) = delete;
    ColumnModel& operator=(const ColumnModel&) = delete;

    const Profile& profile() const { return m_profile; }
    // The gas tables not read (options.wavenumbers_cm1: none reach them).
    const std::vector<std::string>& skipped_gas_tables() const { return m_gas_tables->skipped(); }
    std::size_t sensor_level() const { return m_sensor_level; }  // index into profile levels
    double visibility_km() const { return m_aerosol->visibility_km(); }

    // True when the deck asks for LOWTRAN 7's Mie phase functions (IEMSCT 2 with IPH 2,
    // or IEMSCT 1: deck_mie_phase).
    bool mie() const { return m_mie.has_value(); }
    // With mie(): the phase function of aerosol region `region` (0-3) at a wavelength as
    // LOWTRAN 7's PHASEF selects it (MiePhaseTable::region: the deck's IHAZE, IVULCN
    // and the boundary layer's humidity); none where it uses Henyey-Greenstein.
    std::optional<TabulatedPhase> mie_phase(int region, double wavelength_um) const;

    // Whether mie_phase() gives a function (without building it).
    bool has_mie_phase(int region, double wavelength_um) const;
    // With has_mie_phase(): the Legendre moments chi_0..chi_nmom of mie_phase(region,
    // wavelength) and its integral (phase_moments with `points` Gauss points per
    // interval) by Chebyshev interpolation in the wavelength between the two index
    // wavelengths it lies between (MiePhaseTable::wavelength_interval), where the
    // function is smooth in it: kMieNodes nodes, their moments formed once per region,
    // interval, nmom and points (thread-safe). Measured over LOWTRAN 7's visible and
    // near-infrared intervals: within 4e-15 of phase_moments at the wavelength itself
    // (2e-10 with 8 nodes; mie_layers_test.cpp).
    // With `grid`, also the function's normalized values on phase_grid (4 pi P /
    // integral, phase_grid::normalized), interpolated alike (their nodes kept too).
    void mie_moments(int region, double wavelength_um, int nmom, int points,
                     std::vector<double>& chi, double& integral,
                     std::vector<double>* grid = nullptr) const;
    static constexpr int kMieNodes = 12;

    // Every layer (bottom first, profile().size() - 1 of them) at wavenumber nu.
    std::vector<LayerOptics> layers(double nu_cm1) const;
    // The column's scattering optical depth at nu: the sum over layers() of tau_rayleigh
    // + tau_aerosol ssa_aerosol (the same numbers, without the gas absorption).
    double scattering_optical_depth(double nu_cm1) const;

    // Equivalent Beer's-law gas absorption depth of every layer (bottom first) such that
    // the vertical band-model transmittance from level `pivot` to every other level is
    // reproduced exactly. The band model is not multiplicative (a layer absorbs less
    // behind a path that has saturated its lines), so no one set of layer depths is
    // exact for every path: pivot = top suits the solar beam (layers() uses it),
    // pivot = 0 the emission reaching the ground (L_de), pivot = the sensor level the
    // emission reaching the sensor (L_ue).
    std::vector<double> gas_depths_from(double nu_cm1, std::size_t pivot) const;
    // The exponential-sum terms of the gas absorption at nu (GasColumn::absorption_terms,
    // depths bottom first, negative ones 0): a fit within `tol` (transmittance) over path
    // amounts up to kGasPathFactor times the vertical column, at most max_terms terms per
    // gas. Where every gas is weak enough for Beer's law: one term, weight 1, whose
    // depths are layers()' tau_gas (`equivalent`). build_radiance asks kGasFitTolerance
    // for scattered sunlight, and kGasThermalTolerance where layers emit: emission goes
    // as the absorptance 1 - T, a few percent in the windows, so 0.005 in T is too
    // coarse there (man build_radiance(1)).
    static constexpr double kGasFitTolerance = 0.005;
    static constexpr double kGasThermalTolerance = 0.001;
    static constexpr double kGasPathFactor = 20;  // down and up at 84 deg from the zenith
    // `pairs`: a second gas that overlaps the first strongly is fitted too (GasColumn::
    // absorption_terms); build_radiance asks it for scattered sunlight only. Where layers
    // emit, term_depths_from makes the gases not fitted exact on vertical paths from the
    // pivot, which a second fit within tol / 3 in transmittance does not beat against
    // absorptances of a few percent (measured: L_ue at 2500 cm-1 -0.44 % -> -1.07 % of
    // the formal solution) at 50-odd terms a sample between 500 and 3000 cm-1.
    GasColumn::Terms gas_terms(double nu_cm1, int max_terms, double tol, bool pairs = false) const;
    // For layer emission: term t's depths with the gases not fitted exact from `pivot`.
    std::vector<double> term_depths_from(double nu_cm1, const GasColumn::Terms& terms,
                                         std::size_t t, std::size_t pivot) const;

    static std::vector<LayerOptics> with_gas_depths(std::vector<LayerOptics> layers,
                                                    const std::vector<double>& gas);

    // Direct (unscattered) transmittance between levels i < j along the refracted
    // line of sight through spherical shells (spherical_path.hpp) whose local zenith
    // angle at level j is acos(mu): band-model gas transmittance of the slant amounts
    // times exp(-sum of air mass times Rayleigh + aerosol extinction).
    double direct_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                                std::size_t level_i, std::size_t level_j, double mu) const;
    // Direct transmittance of the sun's beam, true zenith acos(mu0) (outside the
    // atmosphere), from the top down to `level` along its refracted path; 0 when the
    // sun lies below the refracted horizon.
    double sun_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                             std::size_t level, double mu0) const;
    // The refracted rays behind them (computed once per argument, then cached).
    const Ray& sun_ray(std::size_t level, double mu0) const;
    const Ray& view_ray(std::size_t level_i, std::size_t level_j, double mu) const;
    const Shells& shells() const { return m_shells; }

private:
    Profile m_profile;
    std::size_t m_sensor_level = 0;
    std::optional<AerosolModel> m_aerosol;
    std::vector<std::array<double, 4>> m_aerosol055;  // per layer: slab_columns055
    std::optional<CloudModel> m_cloud;                // ICLD 1-10: the water cloud
    std::optional<RainModel> m_rain;                  // ICLD 6-10, RAINRT
    std::optional<CirrusModel> m_cirrus;              // ICLD 18, 19
    std::optional<MiePhaseTable> m_mie;               // IPH 2 or IEMSCT 1
    int m_ihaze = 0, m_ivulcn = 0;
    std::array<bool, 4> m_user_region{};      // CARD 2D IREG: Henyey-Greenstein with its ASYM
    std::unique_ptr<GasTables> m_gas_tables;  // GasColumn may refer to both: the model
    std::unique_ptr<GasColumn> m_gas;         // is neither copied nor moved
    std::vector<LayerOptics> layers_without_gas(double nu_cm1) const;
    double slant_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                               std::size_t level_i, std::size_t level_j, const Ray& ray) const;
    Shells m_shells;
    ShellNodes m_shell_nodes;  // for the sun's and the views' rays
    struct MieNodes {
        std::vector<double> wavelength_um, weight;  // Chebyshev nodes, barycentric weights
        std::vector<std::vector<double>> chi;       // per node
        std::vector<double> integral;               // per node
        std::vector<std::vector<double>> grid;      // per node: phase_grid::normalized
    };
    mutable std::mutex m_mie_mutex;  // guards m_mie_nodes
    mutable std::map<std::tuple<int, double, int, int>, MieNodes> m_mie_nodes;
    using RayKey = std::tuple<int, std::size_t, std::size_t, double>;
    mutable std::mutex m_ray_mutex;  // guards m_rays (node-based: references stay valid)
    mutable std::map<RayKey, Ray> m_rays;
    const Ray& cached_ray(const RayKey& key, const std::function<Ray()>& trace) const;
};

}  // namespace sigchain::atmos
