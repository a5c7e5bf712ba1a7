// A Landsat band as sigchain's sensor: calibration (MTL, the ETM+ gain table) and the
// response on a wavenumber grid with the wavelength Jacobian (man landsat_sensor(1)).
#include "sensor_response/landsat.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"
#include "sensor_response/band.hpp"

namespace sigchain::sensor_response {

namespace {

// Chander, Markham and Helder (2009), table 1, ETM+ after 1 July 2000:
// band, LMIN and LMAX at low gain, LMIN and LMAX at high gain (W m-2 sr-1 um-1).
struct EtmRow {
    const char* band;
    double low_min, low_max, high_min, high_max;
};
constexpr EtmRow kEtmTable[] = {
    {"1", -6.2, 293.7, -6.2, 191.6},   {"2", -6.4, 300.9, -6.4, 196.5},
    {"3", -5.0, 234.4, -5.0, 152.9},   {"4", -5.1, 241.1, -5.1, 157.4},
    {"5", -1.0, 47.57, -1.0, 31.06},   {"6", 0.0, 17.04, 3.2, 12.65},
    {"6_VCID_1", 0.0, 17.04, 3.2, 12.65}, {"6_VCID_2", 0.0, 17.04, 3.2, 12.65},
    {"7", -0.35, 16.54, -0.35, 10.80}, {"8", -4.7, 243.1, -4.7, 158.3},
};

const char* gain_word(char g) { return g == 'L' ? "low" : g == 'H' ? "high" : "no"; }

}  // namespace

std::optional<EtmGainRange> etm_gain_range(const std::string& band, char gain_state) {
    for (const auto& row : kEtmTable) {
        if (band != row.band) continue;
        if (gain_state == 'L') return EtmGainRange{row.low_min, row.low_max};
        if (gain_state == 'H') return EtmGainRange{row.high_min, row.high_max};
    }
    return std::nullopt;
}

Rescaling etm_table_rescaling(const EtmGainRange& r) {
    const double mult = (r.lmax - r.lmin) / (255.0 - 1.0);
    return {mult, r.lmin - mult * 1.0};
}

bool is_etm(const io::Mtl& mtl) { return mtl.sensor == "ETM"; }

std::map<std::string, char> parse_gain_overrides(const std::string& text) {
    std::map<std::string, char> out;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t comma = text.find(',', pos);
        if (comma == std::string::npos) comma = text.size();
        const std::string item = text.substr(pos, comma - pos);
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || item.size() != eq + 2 ||
            (item[eq + 1] != 'H' && item[eq + 1] != 'L'))
            throw UsageError("--gain: " + text + ": expected BAND=H|L[,BAND=H|L...], found '" +
                             item + "'");
        const std::string band = item.substr(0, eq);
        if (!etm_gain_range(band, 'H'))
            throw UsageError("--gain: " + text + ": band '" + band +
                             "' has no ETM+ gain states (1-5, 6_VCID_1, 6_VCID_2, 7, 8)");
        out[band] = item[eq + 1];
        pos = comma + 1;
    }
    return out;
}

std::optional<BandCalibration> band_calibration(const io::Mtl& mtl, const std::string& name,
                                                const std::map<std::string, char>& overrides,
                                                const std::string& mtl_path,
                                                const Reporter& report) {
    const io::MtlBand* b = io::find_band(mtl, name);
    BandCalibration c;
    c.name = name;
    if (b) c.gain_state = b->gain_state, c.qcal_min = b->qcal_min, c.qcal_max = b->qcal_max;
    const bool etm = is_etm(mtl);
    if (auto o = overrides.find(name); o != overrides.end()) {
        if (!etm) throw UsageError("--gain: " + mtl.spacecraft + " " + mtl.sensor + " has no gain states");
        c.gain_state = o->second;
        c.rescaling = etm_table_rescaling(*etm_gain_range(name, c.gain_state));
        c.source = std::string("table (") + gain_word(c.gain_state) + " gain, --gain)";
        return c;
    }
    if (b && b->radiance_mult) {
        c.rescaling = {*b->radiance_mult, *b->radiance_add};
        c.source = "MTL";
        if (etm && c.gain_state) {
            const auto table = etm_table_rescaling(*etm_gain_range(name, c.gain_state));
            if (std::abs(c.rescaling.mult / table.mult - 1) > 0.01) {
                const auto other = etm_table_rescaling(*etm_gain_range(name, c.gain_state == 'H' ? 'L' : 'H'));
                const bool matches_other = std::abs(c.rescaling.mult / other.mult - 1) <= 0.01;
                report.warn(mtl_path + ":" + std::to_string(b->rescaling_line) + ": band " + name +
                            ": radiance rescaling " + format_number(c.rescaling.mult) +
                            " per DN is not the " + gain_word(c.gain_state) + "-gain value " +
                            format_number(table.mult) + " of Chander et al. (2009)" +
                            (matches_other ? std::string(" but the ") + gain_word(c.gain_state == 'H' ? 'L' : 'H') + "-gain one"
                                           : std::string()) +
                            " (the file's gain state on line " + std::to_string(b->gain_line) +
                            "); the file's rescaling is used (--gain " + name + "=H|L to choose)");
            }
        }
        return c;
    }
    if (etm && c.gain_state && etm_gain_range(name, c.gain_state)) {
        c.rescaling = etm_table_rescaling(*etm_gain_range(name, c.gain_state));
        c.source = std::string("table (") + gain_word(c.gain_state) + " gain)";
        return c;
    }
    return std::nullopt;
}

double sen_gain(const Rescaling& r) { return 1e4 / r.mult; }
double sen_bias(const Rescaling& r) { return -r.add / r.mult; }

double response_area_nm(const std::vector<double>& wl, const std::vector<double>& r, double a,
                        double b) {
    // The exact integral of the piecewise-linear function through (wl[i], max(r[i], 0)).
    const std::size_t n = wl.size();
    a = std::max(a, wl.front()), b = std::min(b, wl.back());
    if (!(b > a)) return 0;
    auto value = [&](std::size_t i) { return std::max(r[i], 0.0); };
    auto at = [&](std::size_t i, double x) {  // on the segment [wl[i], wl[i+1]]
        const double t = (x - wl[i]) / (wl[i + 1] - wl[i]);
        return value(i) + t * (value(i + 1) - value(i));
    };
    std::size_t i = interval_index(wl, a);  // a in [wl.front(), wl.back())
    double sum = 0;
    for (; i + 1 < n && wl[i] < b; ++i) {
        const double lo = std::max(a, wl[i]), hi = std::min(b, wl[i + 1]);
        if (hi > lo) sum += (hi - lo) * (at(i, lo) + at(i, hi)) / 2;
    }
    return sum;
}

BandSpectrum band_spectrum(const std::vector<double>& wl, const std::vector<double>& r,
                           const SpectralOptions& opt) {
    double peak = 0;
    for (double v : r) peak = std::max(peak, v);
    if (!(peak > 0)) throw std::invalid_argument("the response has no positive value");
    const double cut = opt.threshold * peak;
    std::size_t first = 0, last = r.size() - 1;
    while (r[first] < cut || r[first] <= 0) ++first;
    while (r[last] < cut || r[last] <= 0) --last;
    // The span's ends: where the response, linear between nodes, crosses the threshold.
    auto crossing = [&](std::size_t below, std::size_t above) {
        const double r0 = std::max(r[below], 0.0), r1 = std::max(r[above], 0.0);
        return wl[below] + (cut - r0) / (r1 - r0) * (wl[above] - wl[below]);
    };
    BandSpectrum s;
    s.threshold_lo_nm = first > 0 ? crossing(first - 1, first) : wl[first];
    s.threshold_hi_nm = last + 1 < r.size() ? crossing(last + 1, last) : wl[last];
    const double nu_lo = 1e7 / s.threshold_hi_nm, nu_hi = 1e7 / s.threshold_lo_nm;  // cm-1
    auto round2 = [](double x) { return std::round(x * 100) / 100; };
    long count = 0;
    if (opt.increment_cm1 > 0) {
        const double inc = opt.increment_cm1;
        s.band.min_wavenumber_cm1 = std::floor(nu_lo / inc) * inc;
        s.band.max_wavenumber_cm1 = std::ceil(nu_hi / inc) * inc;
        s.band.increment_cm1 = inc;
    } else {
        // The threshold span in samples-1 steps of 0.01 cm-1 multiples, centred on it.
        const double inc = std::ceil((nu_hi - nu_lo) / (opt.samples - 1) * 100) / 100;
        s.band.min_wavenumber_cm1 = round2(nu_lo - ((opt.samples - 1) * inc - (nu_hi - nu_lo)) / 2);
        s.band.max_wavenumber_cm1 = round2(s.band.min_wavenumber_cm1 + (opt.samples - 1) * inc);
        s.band.increment_cm1 = inc;
    }
    count = s.band.sample_count();
    // The .rad's order: wavenumber decreasing from the maximum, wavelength increasing.
    const double inc = s.band.increment_cm1;
    std::vector<double> nu(count), wl_um(count);
    for (long k = 0; k < count; ++k) {
        nu[k] = s.band.max_wavenumber_cm1 - k * inc;
        wl_um[k] = um_from_cm1(nu[k]);
    }
    // sensorize weights sample k by R_k x w_k (w_k its midpoint width in um); R_k = A_k / w_k
    // makes that weight A_k, the response's area over the sample's interval nu_k +- inc/2.
    const std::vector<double> widths = sample_widths_um(wl_um, static_cast<int>(count));
    double captured = 0;
    for (long k = 0; k < count; ++k) {
        const double area_nm = response_area_nm(wl, r, 1e7 / (nu[k] + inc / 2), 1e7 / (nu[k] - inc / 2));
        captured += area_nm;
        s.response.push_back(area_nm / 1000 / widths[k]);
    }
    s.captured_fraction = captured / response_area_nm(wl, r, wl.front(), wl.back());
    return s;
}

}  // namespace sigchain::sensor_response
