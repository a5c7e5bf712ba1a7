// IPH 2 in build_radiance's solver (see mie_layers.hpp).
#include "atmos/mie_layers.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "atmos/mie_phase.hpp"
#include "atmos/rayleigh.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kMie0 = 1;  // component index of region 0; 0 is Rayleigh
constexpr std::size_t kHg0 = 5;   // first Henyey-Greenstein component

// Where a cosine falls on the grid (phase_grid): node i and the weight w of node i + 1.
struct GridPoint {
    std::size_t i = 0;
    double w = 0;
};
GridPoint grid_point(double x) {
    const double a = phase_grid::position(std::acos(x) * 180 / kPi);
    const std::size_t i = std::min(static_cast<std::size_t>(a), phase_grid::kSize - 2);
    return {i, std::clamp(a - static_cast<double>(i), 0.0, 1.0)};
}

// The grid points of the last few sets of cosines asked for a mean on this thread: the
// TMS correction's azimuthal means ask the same cosines (those of the sun and the
// tables' directions) in every solve of a run.
const std::vector<GridPoint>& grid_points(const double* xs, int n) {
    struct Entry {
        std::vector<double> xs;
        std::vector<GridPoint> points;
    };
    constexpr std::size_t kEntries = 8;
    thread_local std::array<Entry, kEntries> cache;
    thread_local std::size_t next = 0;
    for (const Entry& e : cache)
        if (e.xs.size() == static_cast<std::size_t>(n) && std::equal(e.xs.begin(), e.xs.end(), xs))
            return e.points;
    Entry& e = cache[next];
    next = (next + 1) % kEntries;
    e.xs.assign(xs, xs + n);
    e.points.clear();
    for (int k = 0; k < n; ++k) e.points.push_back(grid_point(xs[k]));
    return e.points;
}

// The components' values at one cosine: Rayleigh from its moments, the Mie functions
// linear between grid nodes (the tabulated function is ln-linear between its nodes;
// at its steepest, 1.4 per deg in ln P at 0-2 deg, a chord 0.1 deg long departs from
// it by under 0.3 %; beyond 20 deg the slopes stay under 0.1 per deg, under 0.04 % over
// 0.5 deg), Henyey-Greenstein exactly.
struct Components {
    std::array<double, 3> rayleigh{};
    std::array<const std::vector<double>*, 4> grid{};
    std::vector<double> hg_g;
    double rayleigh_at(double x) const {
        return 1 + 3 * rayleigh[1] * x + 5 * rayleigh[2] * (1.5 * x * x - 0.5);
    }
    double mie_at(std::size_t r, GridPoint p) const {  // region r's function, linear on the grid
        if (!grid[r]) return 0;
        const std::vector<double>& g = *grid[r];
        return g[p.i] + p.w * (g[p.i + 1] - g[p.i]);
    }
    double hg_at(std::size_t h, double x) const {  // (1 - g^2) / (1 + g^2 - 2 g x)^1.5
        const double g = hg_g[h];
        return (1 - g * g) / std::pow(1 + g * g - 2 * g * x, 1.5);
    }
    void evaluate(double x, double* out) const {
        out[0] = rayleigh_at(x);
        const GridPoint p = grid_point(x);
        for (std::size_t r = 0; r < 4; ++r) out[kMie0 + r] = mie_at(r, p);
        for (std::size_t h = 0; h < hg_g.size(); ++h) out[kHg0 + h] = hg_at(h, x);
    }
    // ExactPhase::mean: each component's sum over k of its value at xs[k] / n, in k order
    // (evaluate's numbers), the grid points kept between solves (grid_points).
    void mean(const double* xs, int n, double* out) const {
        const std::vector<GridPoint>& points = grid_points(xs, n);
        out[0] = 0;
        for (int k = 0; k < n; ++k) out[0] += rayleigh_at(xs[k]) / n;
        for (std::size_t r = 0; r < 4; ++r) {
            double& m = out[kMie0 + r];
            m = 0;
            for (int k = 0; k < n; ++k) m += mie_at(r, points[static_cast<std::size_t>(k)]) / n;
        }
        for (std::size_t h = 0; h < hg_g.size(); ++h) {
            double& m = out[kHg0 + h];
            m = 0;
            for (int k = 0; k < n; ++k) m += hg_at(h, xs[k]) / n;
        }
    }
};

std::size_t hg_index(std::vector<double>& gs, double g) {
    const auto it = std::find(gs.begin(), gs.end(), g);
    if (it != gs.end()) return static_cast<std::size_t>(it - gs.begin());
    gs.push_back(g);
    return gs.size() - 1;
}

}  // namespace

namespace {

// The fewest Gauss points per interval for the moments asked (mie_phase.hpp).
int moment_points(int nmom) { return nmom <= 32 ? 8 : nmom <= 64 ? 16 : 64; }

}  // namespace

MieOptics mie_optics(const ColumnModel& column, double wavelength_um, int nmom) {
    MieOptics m;
    for (std::size_t r = 0; r < 4; ++r) {
        if (!column.has_mie_phase(static_cast<int>(r), wavelength_um)) continue;
        m.has[r] = true;
        double integral = 0;
        column.mie_moments(static_cast<int>(r), wavelength_um, nmom, moment_points(nmom), m.chi[r],
                           integral, &m.grid[r]);
    }
    return m;
}

MieOptics mie_optics(const std::array<std::optional<TabulatedPhase>, 4>& regions, int nmom) {
    MieOptics m;
    for (std::size_t r = 0; r < 4; ++r) {
        const auto& p = regions[r];
        if (!p) continue;
        m.has[r] = true;
        double integral = 0;
        m.chi[r] = phase_moments(*p, nmom, &integral, moment_points(nmom));
        m.grid[r].resize(phase_grid::kSize);
        phase_grid::normalized(*p, integral, m.grid[r].data());
    }
    return m;
}

namespace {

// Merged layer i (the column's layers kept[i] to kept[i + 1]): its optical depth added to
// l.tau; returned, its scattering optical depth per component (Rayleigh, the Mie
// regions, then the Henyey-Greenstein rests, whose asymmetries comp.hg_g receives).
std::vector<double> component_scattering(const std::vector<LayerOptics>& col,
                                         std::size_t begin, std::size_t end, Components& comp,
                                         rt::Layer& l) {
    std::vector<double> sc(kHg0, 0.0);
    for (std::size_t k = begin; k < end; ++k) {
        const LayerOptics& c = col[k];
        const double aer = c.tau_aerosol * c.ssa_aerosol;
        l.tau += c.tau_rayleigh + aer + c.tau_aerosol * (1 - c.ssa_aerosol) + c.tau_gas;
        sc[0] += c.tau_rayleigh;
        double rest = aer;
        for (std::size_t r = 0; r < 4; ++r)
            sc[kMie0 + r] += c.tau_scat_mie[r], rest -= c.tau_scat_mie[r];
        if (rest <= 1e-9 * aer) continue;  // rounding of the regions' sum: no rest
        const std::size_t h = kHg0 + hg_index(comp.hg_g, c.g_other);
        sc.resize(std::max(sc.size(), h + 1), 0.0);
        sc[h] += rest;
    }
    return sc;
}

// The moments g^k (k = 0..moments) of each Henyey-Greenstein component, made on first use.
class HgMoments {
public:
    HgMoments(const Components& comp, int moments) : m_comp(comp), m_moments(moments) {}
    const std::vector<double>& operator()(std::size_t h) {
        for (std::size_t n = m_chi.size(); n <= h; ++n) {
            m_chi.emplace_back();
            for (int j = 0; j <= m_moments; ++j) m_chi[n].push_back(std::pow(m_comp.hg_g[n], j));
        }
        return m_chi[h];
    }

private:
    const Components& m_comp;
    int m_moments;
    std::vector<std::vector<double>> m_chi;
};

// The layer's phase-function moments from its scattering per component `sc` (sum
// `scat`), normalised by it.
void mix_moments(const std::vector<double>& sc, double scat,
                 const std::array<double, 3>& rayleigh, const MieOptics& mie, HgMoments& hg_chi,
                 int moments, std::vector<double>& pm) {
    // Moment k sums scattering x chi_k over the components in component order; the
    // components are taken one at a time, each over every moment.
    pm.assign(static_cast<std::size_t>(moments) + 1, 0.0);
    for (std::size_t c = 0; c < sc.size(); ++c) {
        if (sc[c] == 0) continue;
        const double w = sc[c];
        if (c == 0) {
            for (int k = 0; k <= moments; ++k) pm[k] += w * (k < 3 ? rayleigh[k] : 0.0);
        } else if (c < kHg0) {
            const std::vector<double>& chi = mie.chi[c - kMie0];
            const int n = static_cast<int>(chi.size());
            for (int k = 0; k <= moments; ++k) pm[k] += w * (k < n ? chi[k] : 0.0);
        } else {
            const std::vector<double>& chi = hg_chi(c - kHg0);
            for (int k = 0; k <= moments; ++k) pm[k] += w * chi[k];
        }
    }
    for (int k = 0; k <= moments; ++k) pm[k] = scat > 0 ? pm[k] / scat : (k == 0 ? 1.0 : 0.0);
}

// The exact phase functions of the solver's layers: each layer's weights per component
// (its scattering fractions, scat_c) and the components' functions.
void set_exact_phase(const std::shared_ptr<Components>& comp, std::size_t layers,
                     const std::vector<std::vector<double>>& scat_c, rt::ExactPhase& exact) {
    const std::size_t nc = kHg0 + comp->hg_g.size();
    exact.components = nc;
    exact.weights.assign(layers * nc, 0.0);
    for (std::size_t n = 0; n < layers; ++n)
        std::copy(scat_c[n].begin(), scat_c[n].end(), exact.weights.begin() + n * nc);
    exact.evaluate = [comp](double x, double* v) { comp->evaluate(x, v); };
    exact.mean = [comp](const double* xs, int n, double* v) { comp->mean(xs, n, v); };
}

}  // namespace

std::vector<rt::Layer> mie_solver_layers(const std::vector<LayerOptics>& col,
                                         const std::vector<std::size_t>& kept, const MieOptics& mie,
                                         int moments, rt::ExactPhase* exact) {
    const auto rayleigh = rayleigh_phase_moments();
    auto comp = std::make_shared<Components>();
    for (int k = 0; k < 3; ++k) comp->rayleigh[k] = rayleigh[k];
    for (std::size_t r = 0; r < 4; ++r)
        if (mie.has[r]) comp->grid[r] = &mie.grid[r];
    std::vector<rt::Layer> out;
    std::vector<std::vector<double>> scat_c;  // per output layer: scattering per component
    HgMoments hg_chi(*comp, moments);
    for (std::size_t i = kept.size() - 1; i-- > 0;) {
        rt::Layer l;
        std::vector<double> sc = component_scattering(col, kept[i], kept[i + 1], *comp, l);
        double scat = 0;
        for (double v : sc) scat += v;
        l.ssa = l.tau > 0 ? std::clamp(scat / l.tau, 0.0, 1.0) : 0.0;
        mix_moments(sc, scat, rayleigh, mie, hg_chi, moments, l.pmom);
        for (double& v : sc) v = scat > 0 ? v / scat : 0.0;
        scat_c.push_back(std::move(sc));
        out.push_back(std::move(l));
    }
    if (exact) set_exact_phase(comp, out.size(), scat_c, *exact);
    return out;
}

}  // namespace sigchain::atmos
