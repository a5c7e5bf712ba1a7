// The MTF chain and its frequency-domain filter (FFTW3, double precision).
#include "sensor_response/mtf.hpp"

#include <fftw3.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>

#include "core/error.hpp"

namespace sigchain::sensor_response {

namespace {

constexpr double pi = std::numbers::pi;

// FFTW's planner (and fftw_destroy_plan) are not thread-safe; fftw_execute is.
std::mutex& planner_mutex() {
    static std::mutex m;
    return m;
}

struct FftwFree {
    void operator()(void* p) const { fftw_free(p); }
};

struct PlanDeleter {
    void operator()(fftw_plan p) const {
        std::lock_guard<std::mutex> lock(planner_mutex());
        fftw_destroy_plan(p);
    }
};
using Plan = std::unique_ptr<std::remove_pointer_t<fftw_plan>, PlanDeleter>;

bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

void require(bool ok, const std::string& message) {
    if (!ok) throw UsageError(message);
}

// A frequency index of an n-point DFT in cycles/sample: k/n for k <= n/2, else (k − n)/n.
double frequency(long k, long n) {
    return static_cast<double>(k <= n / 2 ? k : k - n) / static_cast<double>(n);
}

}  // namespace

double sinc(double x) {
    if (x == 0) return 1;
    return std::sin(pi * x) / (pi * x);
}

double diffraction_mtf(double nu, double cutoff) {
    // Goodman, Introduction to Fourier Optics, section 6.3: circular pupil, incoherent light.
    const double x = std::abs(nu) / cutoff;
    if (x >= 1) return 0;
    return (2 / pi) * (std::acos(x) - x * std::sqrt(1 - x * x));
}

double diffraction_cutoff_cyc_per_px(double pitch_um, double wavelength_um, double f_number) {
    // ν_c = 1/(λN) cycles per unit length; times the pitch gives cycles per pixel.
    return pitch_um / (wavelength_um * f_number);
}

double gaussian_mtf(double nu, double sigma_px) {
    return std::exp(-2 * pi * pi * sigma_px * sigma_px * nu * nu);
}

double detector_mtf(double nu, double width_px) { return std::abs(sinc(width_px * nu)); }

double motion_otf(double nu_along, double smear_px) { return sinc(smear_px * nu_along); }

double butterworth_gain(double f_hz, double cutoff_hz, int poles) {
    return 1 / std::sqrt(1 + std::pow(std::abs(f_hz) / cutoff_hz, 2 * poles));
}

double electronics_mtf(double nu_along_scan, double dwell_s, double cutoff_hz, int poles) {
    return butterworth_gain(nu_along_scan / dwell_s, cutoff_hz, poles);
}

void MtfParams::check() const {
    require(f_number == 0 || finite_positive(f_number), "--mtf-fnumber must be a positive number");
    require(pitch_um == 0 || finite_positive(pitch_um), "--mtf-pitch must be a positive number");
    require((f_number > 0) == (pitch_um > 0), "give --mtf-fnumber and --mtf-pitch together");
    require(finite_positive(fill_factor) && fill_factor <= 1,
            "--mtf-fill must be greater than 0 and at most 1");
    require(std::isfinite(defocus_sigma_px) && defocus_sigma_px >= 0,
            "--mtf-defocus must not be negative");
    require(std::isfinite(smear_px) && smear_px >= 0 && std::isfinite(smear_angle_deg),
            "--mtf-smear: the smear must not be negative and the angle must be a number");
    require(electronics_cutoff_hz == 0 ||
                (finite_positive(electronics_cutoff_hz) && finite_positive(dwell_s)),
            "--mtf-electronics: the cutoff and the dwell time must be positive numbers");
    require(poles >= 1 && poles <= 8, "--mtf-electronics: the number of poles must be 1 to 8");
}

MtfChain::MtfChain(const MtfParams& params, double wavelength_um) : m_p(params) {
    if (m_p.f_number > 0)
        m_cutoff = diffraction_cutoff_cyc_per_px(m_p.pitch_um, wavelength_um, m_p.f_number);
    const double a = m_p.smear_angle_deg * pi / 180;
    m_cos = std::cos(a);
    m_sin = std::sin(a);
}

MtfTerms MtfChain::terms(double nu_x, double nu_y) const {
    MtfTerms t;
    const double nu_r = std::hypot(nu_x, nu_y);
    if (m_cutoff > 0) t.optics = diffraction_mtf(nu_r, m_cutoff);
    if (m_p.defocus_sigma_px > 0) t.optics *= gaussian_mtf(nu_r, m_p.defocus_sigma_px);
    // A rectangular detector: the footprint's transform is separable.
    t.detector = detector_mtf(nu_x, m_p.fill_factor) * detector_mtf(nu_y, m_p.fill_factor);
    if (m_p.smear_px > 0)
        t.motion = std::abs(motion_otf(nu_x * m_cos + nu_y * m_sin, m_p.smear_px));
    if (m_p.electronics_cutoff_hz > 0)
        t.electronics = electronics_mtf(nu_x, m_p.dwell_s, m_p.electronics_cutoff_hz, m_p.poles);
    t.system = t.optics * t.detector * t.motion * t.electronics;
    return t;
}

double MtfChain::transfer(double nu_x, double nu_y) const {
    const MtfTerms t = terms(nu_x, nu_y);
    // The motion term keeps its sign (a box smear reverses contrast past ν = 1/d); the
    // others are non-negative on |ν| <= 0.5 (the detector width is at most one pixel).
    // The electronics is taken as zero-phase (its group delay, a shift, is left out).
    const double sign =
        m_p.smear_px > 0 && motion_otf(nu_x * m_cos + nu_y * m_sin, m_p.smear_px) < 0 ? -1 : 1;
    return sign * t.system;
}

std::vector<float> apply_mtf(const std::vector<float>& plane, long rows, long columns,
                             const MtfChain& chain) {
    const long m = 2 * rows, n = 2 * columns, nc = n / 2 + 1;
    std::unique_ptr<double, FftwFree> real(
        static_cast<double*>(fftw_malloc(sizeof(double) * m * n)));
    std::unique_ptr<fftw_complex, FftwFree> spectrum(
        static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * m * nc)));
    if (!real || !spectrum) throw std::bad_alloc();
    Plan forward, backward;
    {
        std::lock_guard<std::mutex> lock(planner_mutex());
        forward.reset(fftw_plan_dft_r2c_2d(static_cast<int>(m), static_cast<int>(n), real.get(),
                                           spectrum.get(), FFTW_ESTIMATE));
        backward.reset(fftw_plan_dft_c2r_2d(static_cast<int>(m), static_cast<int>(n),
                                            spectrum.get(), real.get(), FFTW_ESTIMATE));
    }
    // Half-sample symmetric mirror: padded index i maps to i (i < rows) or 2·rows − 1 − i.
    double* r = real.get();
    for (long i = 0; i < m; ++i) {
        const long si = i < rows ? i : m - 1 - i;
        for (long j = 0; j < n; ++j) {
            const long sj = j < columns ? j : n - 1 - j;
            r[i * n + j] = plane[static_cast<std::size_t>(si * columns + sj)];
        }
    }
    fftw_execute(forward.get());
    // FFTW's transforms are unnormalised: the round trip multiplies by m·n.
    const double scale = 1.0 / (static_cast<double>(m) * static_cast<double>(n));
    fftw_complex* s = spectrum.get();
    for (long i = 0; i < m; ++i) {
        const double nu_y = frequency(i, m);
        for (long j = 0; j < nc; ++j) {
            const double h = chain.transfer(static_cast<double>(j) / n, nu_y) * scale;
            s[i * nc + j][0] *= h;
            s[i * nc + j][1] *= h;
        }
    }
    fftw_execute(backward.get());
    std::vector<float> out(static_cast<std::size_t>(rows * columns));
    for (long i = 0; i < rows; ++i)
        for (long j = 0; j < columns; ++j)
            out[static_cast<std::size_t>(i * columns + j)] = static_cast<float>(r[i * n + j]);
    return out;
}

MtfBandReport apply_band_mtf(std::vector<float>& plane, long rows, long columns,
                             const MtfParams& params, double wavelength_um,
                             const std::string& cube_path) {
    if (params.f_number > 0 && !(wavelength_um > 0))
        throw DataError({cube_path, 0},
                        "no wavelength list: the diffraction MTF (--mtf-fnumber) needs each "
                        "band's centre wavelength");
    const MtfChain chain(params, wavelength_um);
    plane = apply_mtf(plane, rows, columns, chain);
    return {wavelength_um, chain.terms(0.5, 0)};
}

}  // namespace sigchain::sensor_response
