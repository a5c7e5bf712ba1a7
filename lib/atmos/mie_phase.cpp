// LOWTRAN 7's Mie aerosol phase functions (see mie_phase.hpp).
#include "atmos/mie_phase.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string_view>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"
#include "core/vector_clones.hpp"
#include "rt/quadrature.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kPi = std::numbers::pi;

// Interpolates a to b at fraction f: in ln when both are positive (PHASEF).
double log_lerp(double a, double b, double f) {
    if (a > 0 && b > 0) return a * std::pow(b / a, f);
    return a + f * (b - a);
}

// Calls row(reader, fields) for each line of a whitespace table (comment lines skipped),
// each of `columns` fields; DataError unless there are `rows` lines. Messages name the
// file and line (FieldReader's).
template <class Row>
void read_rows(const std::string& path, std::size_t columns, std::size_t rows, Row row) {
    const TextInput in = TextInput::from_file(path);
    FieldReader reader(in);
    reader.require_not_empty("a table row");
    const std::string what = "a row of " + std::to_string(columns) + " fields";
    std::size_t count = 0;
    for (; !reader.at_end(); ++count) row(reader, reader.fields(columns, what));
    if (count != rows)
        throw DataError(
            in.at(0), "expected " + std::to_string(rows) + " rows, found " + std::to_string(count));
}

// Legendre polynomials P_0..P_n at x into out.
void legendre(double x, std::vector<double>& out) {
    out[0] = 1;
    if (out.size() > 1) out[1] = x;
    for (std::size_t k = 2; k < out.size(); ++k)
        out[k] = ((2 * k - 1) * x * out[k - 1] - (k - 1) * out[k - 2]) / k;
}

// ln P at the nodes where both ends of each interval are positive (PHASEF's ln-linear
// interpolation), so that a value inside an interval is one exp instead of a pow:
// exp(ln a + f (ln b - ln a)) = a (b / a)^f, equal to rounding.
struct LogNodes {
    std::vector<double> ln;         // ln P (0 where P <= 0)
    std::vector<char> ln_interval;  // interval i is ln-linear (both ends > 0)
    explicit LogNodes(const std::vector<double>& p) : ln(p.size(), 0.0), ln_interval(p.size(), 0) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if (p[i] > 0) ln[i] = std::log(p[i]);
        for (std::size_t i = 0; i + 1 < p.size(); ++i) ln_interval[i] = p[i] > 0 && p[i + 1] > 0;
    }
};

// The value within interval i at fraction f for the moments: ln P linear in angle, but
// in the intervals touching 0 and 180 deg ln P is quadratic in the distance from the
// pole, flat there. A phase function is smooth on the sphere, so its slope in angle
// vanishes at both poles; a kink there (ln-linear to the pole) would make a cusp whose
// Legendre series converges only as N^-2.
double moment_value(const TabulatedPhase& p, const LogNodes& l, std::size_t i, double f) {
    const double a = p.p_sr1[i], b = p.p_sr1[i + 1];
    if (!l.ln_interval[i]) return a + f * (b - a);
    const double la = l.ln[i], lb = l.ln[i + 1];
    if (i == 0) return std::exp(la + f * f * (lb - la));
    if (i + 2 == p.p_sr1.size()) return std::exp(lb + (1 - f) * (1 - f) * (la - lb));
    return std::exp(la + f * (lb - la));
}

}  // namespace

double TabulatedPhase::at(double angle) const {
    const auto [i, f] = bracket(angle_deg, angle);
    return log_lerp(p_sr1[i], p_sr1[i + 1], f);
}

void TabulatedPhase::at_steps(double start_deg, double step_deg, std::size_t from, std::size_t to,
                              double* out) const {
    const LogNodes l(p_sr1);
    const std::size_t last = angle_deg.size() - 2;  // the last interval
    // The value at x in interval i at fraction f, as at() forms it (by an exp of ln P).
    auto value = [&](std::size_t i, double x) {
        const double f = (x - angle_deg[i]) / (angle_deg[i + 1] - angle_deg[i]);
        const double a = p_sr1[i], b = p_sr1[i + 1];
        return l.ln_interval[i] ? std::exp(l.ln[i] + f * (l.ln[i + 1] - l.ln[i])) : a + f * (b - a);
    };
    auto angle = [&](std::size_t j) { return start_deg + static_cast<double>(j) * step_deg; };
    std::size_t j = from;
    for (; j < to && angle(j) < angle_deg.front(); ++j) out[j - from] = value(0, angle_deg.front());
    // Interval i holds the angles below node i + 1 (bracket()'s), the last one its end too.
    for (std::size_t i = 0; i <= last && j < to; ++i) {
        auto inside = [&](double x) {
            return i < last ? x < angle_deg[i + 1] : x <= angle_deg[i + 1];
        };
        if (!inside(angle(j))) continue;
        double v = value(i, angle(j));
        out[j++ - from] = v;
        if (!l.ln_interval[i]) {
            for (; j < to && inside(angle(j)); ++j) out[j - from] = value(i, angle(j));
            continue;
        }
        const double ratio =
            std::exp((l.ln[i + 1] - l.ln[i]) * step_deg / (angle_deg[i + 1] - angle_deg[i]));
        for (; j < to && inside(angle(j)); ++j) out[j - from] = v *= ratio;
    }
    for (; j < to; ++j) out[j - from] = value(last, angle_deg.back());
}

namespace phase_grid {

double angle_deg(std::size_t i) {
    return i <= 200 ? 0.1 * static_cast<double>(i) : 20 + 0.5 * static_cast<double>(i - 200);
}

double position(double angle_deg) {
    return angle_deg <= 20 ? angle_deg / 0.1 : 200 + (angle_deg - 20) / 0.5;
}

void normalized(const TabulatedPhase& p, double integral, double* out) {
    const double scale = 4 * kPi / integral;  // average over the sphere 1
    // angle_deg's two runs: 0.1 deg steps to 20 deg, 0.5 deg steps beyond.
    p.at_steps(0, 0.1, 0, 201, out);
    p.at_steps(20, 0.5, 1, 321, out + 201);
    for (std::size_t i = 0; i < kSize; ++i) out[i] *= scale;
}

}  // namespace phase_grid

namespace {

// The quadrature of phase_moments for one angle grid: per node (interval i, Gauss point
// q), the weight 2 pi (b - a) w_q sin(t) and P_0..P_nmom(cos t). The same grid (LOWTRAN
// 7's 34 angles) comes back for every spectral sample, so each thread keeps the last
// one: the sums are then formed from the same numbers as without it, bit for bit.
struct MomentNodes {
    std::vector<double> angle_deg;
    int nmom = -1, gauss_points = 0;
    std::size_t per = 0;                       // nodes per interval
    std::vector<double> fraction, weight, pk;  // per node; pk[node * (nmom + 1) + k]
};

const MomentNodes& moment_nodes(const std::vector<double>& angle_deg, int nmom, int gauss_points) {
    thread_local MomentNodes m;
    if (m.nmom == nmom && m.gauss_points == gauss_points && m.angle_deg == angle_deg) return m;
    m = MomentNodes{angle_deg, nmom, gauss_points, 0, {}, {}, {}};
    std::vector<double> nodes, weights, pk(static_cast<std::size_t>(nmom) + 1);
    rt::gauss_half_range(gauss_points, nodes, weights);
    m.per = nodes.size();
    for (std::size_t i = 0; i + 1 < angle_deg.size(); ++i) {
        const double a = angle_deg[i] * kRadPerDeg, b = angle_deg[i + 1] * kRadPerDeg;
        for (std::size_t q = 0; q < nodes.size(); ++q) {
            const double t = a + (b - a) * nodes[q];
            m.fraction.push_back(nodes[q]);
            m.weight.push_back(2 * kPi * (b - a) * weights[q] * std::sin(t));
            legendre(std::cos(t), pk);
            m.pk.insert(m.pk.end(), pk.begin(), pk.end());
        }
    }
    return m;
}

}  // namespace

SIGCHAIN_VECTOR_CLONES
std::vector<double> phase_moments(const TabulatedPhase& p, int nmom, double* integral,
                                  int gauss_points) {
    const MomentNodes& m = moment_nodes(p.angle_deg, nmom, gauss_points);
    const LogNodes l(p.p_sr1);
    std::vector<double> chi(static_cast<std::size_t>(nmom) + 1, 0.0);
    double norm = 0;
    for (std::size_t node = 0; node < m.weight.size(); ++node) {
        const double w = m.weight[node] * moment_value(p, l, node / m.per, m.fraction[node]);
        const double* pk = &m.pk[node * chi.size()];
        norm += w;
        for (std::size_t k = 0; k < chi.size(); ++k) chi[k] += w * pk[k];
    }
    for (double& c : chi) c /= norm;
    chi[0] = 1;
    if (integral) *integral = norm;
    return chi;
}

TabulatedPhase truncate_forward_peak(const TabulatedPhase& p, double cone_deg, double& forward) {
    double whole = 0;
    phase_moments(p, 0, &whole);
    const auto& a = p.angle_deg;
    const std::size_t c = std::size_t(std::lower_bound(a.begin(), a.end(), cone_deg) - a.begin());
    forward = 0;
    TabulatedPhase t = p;
    for (double& v : t.p_sr1) v /= whole;
    if (c == 0 || c + 1 >= a.size()) return t;
    // ln P inside the cone: quadratic in angle, flat at 0 and with the slope s of the
    // interval beyond the cone at its edge: ln P(0) = ln P(cone) - s cone / 2.
    const double v0 = t.p_sr1[c], v1 = t.p_sr1[c + 1];
    const double s = v0 > 0 && v1 > 0 ? std::log(v1 / v0) / (a[c + 1] - a[c]) : 0.0;
    TabulatedPhase out;
    out.angle_deg.push_back(0);
    out.p_sr1.push_back(v0 * std::exp(-s * a[c] / 2));
    out.angle_deg.insert(out.angle_deg.end(), a.begin() + long(c), a.end());
    out.p_sr1.insert(out.p_sr1.end(), t.p_sr1.begin() + long(c), t.p_sr1.end());
    double kept = 0;
    phase_moments(out, 0, &kept);
    forward = std::clamp(1 - kept, 0.0, 1.0);
    for (double& v : out.p_sr1) v /= kept;
    return out;
}

double phase_from_moments(const std::vector<double>& chi, double angle_deg) {
    std::vector<double> pk(chi.size());
    legendre(std::cos(angle_deg * kRadPerDeg), pk);
    double s = 0;
    for (std::size_t k = 0; k < chi.size(); ++k) s += (2 * k + 1) * chi[k] * pk[k];
    return s / (4 * kPi);
}

MiePhaseTable MiePhaseTable::load(const std::string& data_dir) {
    const std::string dir = data_dir + "/atmosphere/lowtran7/";
    MiePhaseTable t;
    t.m_functions.assign(70, {});
    read_rows(dir + "aerosol_phase_functions_mie.txt", 71, 34,
              [&](const FieldReader& r, std::span<const std::string_view> row) {
                  t.m_angles.push_back(r.number(row[0], "an angle"));
                  for (std::size_t n = 0; n < 70; ++n)
                      t.m_functions[n].push_back(r.number(row[n + 1], "a phase function value"));
              });
    // clang-format off
    t.m_wavelengths = {0.2, 0.3,  0.55,  0.6943, 1.06, 1.536, 2,    2.5,  2.7,
                       3,   3.2,  3.39,  5,      6,    7.2,   7.9,  8.7,  9.2,
                       10,  10.59, 12.5, 15,     17.2, 18.5,  21.3, 30,   40};  // PHASEF's WAVE
    // clang-format on
    read_rows(dir + "aerosol_phase_function_index.txt", 29, 26,
              [&](const FieldReader& r, std::span<const std::string_view> row) {
                  std::vector<int> numbers;
                  for (std::size_t w = 2; w < row.size(); ++w) {
                      const double v = r.number(row[w], "a phase function number");
                      if (!(v >= 1 && v <= 70))
                          throw DataError(r.where(), "phase function number outside 1-70");
                      numbers.push_back(static_cast<int>(v));
                  }
                  t.m_index.push_back(std::move(numbers));
              });
    return t;
}

TabulatedPhase MiePhaseTable::function(int number) const {
    return {m_angles, m_functions.at(static_cast<std::size_t>(number - 1))};
}

TabulatedPhase MiePhaseTable::model(int model, double wavelength_um) const {
    const auto& row = m_index.at(static_cast<std::size_t>(model - 1));
    const auto [i, f] = bracket(m_wavelengths, wavelength_um);
    const auto& a = m_functions[static_cast<std::size_t>(row[i] - 1)];
    const auto& b = m_functions[static_cast<std::size_t>(row[i + 1] - 1)];
    TabulatedPhase out{m_angles, {}};
    for (std::size_t k = 0; k < a.size(); ++k) out.p_sr1.push_back(log_lerp(a[k], b[k], f));
    return out;
}

std::pair<double, double> MiePhaseTable::wavelength_interval(double wavelength_um) const {
    const std::size_t i = bracket(m_wavelengths, wavelength_um).k;
    return {m_wavelengths[i], m_wavelengths[i + 1]};
}

bool MiePhaseTable::has_region(int region, int ihaze, double wavelength_um) const {
    if (wavelength_um > m_wavelengths.back()) return false;
    if (region != 0) return true;
    return (ihaze >= 1 && ihaze <= 6) || ihaze == 8 || ihaze == 9;  // region()'s cases
}

std::optional<TabulatedPhase> MiePhaseTable::region(int region, int ihaze, int ivulcn, double rh,
                                                    double wavelength_um) const {
    if (wavelength_um > m_wavelengths.back()) return std::nullopt;
    if (region == 1) return model(18, wavelength_um);
    if (region == 2) {
        const int strat[9] = {21, 21, 22, 23, 22, 23, 21, 21, 23};
        return model(strat[std::clamp(ivulcn, 0, 8)], wavelength_um);
    }
    if (region == 3) return model(26, wavelength_um);
    int first = 0;  // the RH 0 % model of the boundary layer's type
    switch (ihaze) {
        case 1:
        case 2:
            first = 1;
            break;
        case 3:
        case 4:
            first = 5;
            break;
        case 5:
            first = 9;
            break;
        case 6:
            first = 17;
            break;
        case 8:
            return model(24, wavelength_um);
        case 9:
            return model(25, wavelength_um);
        default:  // 10 desert (and 0, no aerosol): Henyey-Greenstein
            return std::nullopt;
    }
    const std::vector<double> rh_nodes = {0, 70, 80, 99};
    const auto [j, f] = bracket(rh_nodes, rh);
    const TabulatedPhase a = model(first + static_cast<int>(j), wavelength_um);
    const TabulatedPhase b = model(first + static_cast<int>(j) + 1, wavelength_um);
    TabulatedPhase out{m_angles, {}};
    for (std::size_t k = 0; k < a.p_sr1.size(); ++k)
        out.p_sr1.push_back(a.p_sr1[k] + f * (b.p_sr1[k] - a.p_sr1[k]));  // linear in RH
    return out;
}

}  // namespace sigchain::atmos
