// The sensor's modulation transfer function chain (optics, detector, image motion,
// electronics), applied to each band in the frequency domain with FFTW3 (sensorize(1), MTF).
//
// Frequencies are in cycles per pixel: the cube's pixel is the detector pitch, so the
// Nyquist frequency is 0.5 cycles/pixel. x runs along a row (column index), y down a
// column (row index).
#pragma once

#include <string>
#include <vector>

namespace sigchain::sensor_response {

// sinc(x) = sin(πx) / (πx), sinc(0) = 1.
double sinc(double x);

// Diffraction MTF of an unobscured circular aperture (Goodman, Introduction to Fourier
// Optics, section 6.3): (2/π)[acos(x) − x√(1−x²)], x = ν/ν_c, 0 beyond ν_c.
// nu and cutoff in the same unit (cycles/pixel here); cutoff > 0.
double diffraction_mtf(double nu, double cutoff);

// The diffraction cutoff ν_c = 1/(λN) in cycles/pixel: pitch_um / (wavelength_um · N).
double diffraction_cutoff_cyc_per_px(double pitch_um, double wavelength_um, double f_number);

// Gaussian MTF of defocus or aberration, the transform of a Gaussian PSF of standard
// deviation sigma_px (pixels): exp(−2π²σ²ν²), ν in cycles/pixel.
double gaussian_mtf(double nu, double sigma_px);

// Detector footprint MTF (Holst, Electro-Optical Imaging System Performance):
// |sinc(p ν)|, p the detector width in pixels (the linear fill factor), ν in cycles/pixel.
double detector_mtf(double nu, double width_px);

// Transfer function of linear image motion of d pixels during the integration time
// (Holst, Electro-Optical Imaging System Performance): sinc(d ν), ν the frequency along
// the motion. Signed: beyond ν = 1/d it is negative (contrast reversal); the MTF is its
// modulus.
double motion_otf(double nu_along, double smear_px);

// Magnitude of an n-pole Butterworth low-pass filter: 1 / √(1 + (f/f_c)^(2n)), f and f_c in Hz.
double butterworth_gain(double f_hz, double cutoff_hz, int poles);

// The electronics of a scanner along scan: the detector sweeps one pixel in the dwell time
// t_d (s), so ν cycles/pixel along scan is the temporal frequency f = ν / t_d (Hz), and the
// MTF is the filter's magnitude there.
double electronics_mtf(double nu_along_scan, double dwell_s, double cutoff_hz, int poles);

// The MTF parameters of a sensor (sensorize --mtf-* options). A term is off when its
// parameter is 0 (the detector term is on whenever the chain is).
struct MtfParams {
    double f_number = 0;               // optics: diffraction when > 0 (needs pitch_um)
    double pitch_um = 0;               // detector pitch, micrometres
    double fill_factor = 1;            // detector width / pitch (linear), 0 < F <= 1
    double defocus_sigma_px = 0;       // Gaussian defocus/aberration, pixels
    double smear_px = 0;               // image motion during integration, pixels
    double smear_angle_deg = 0;        // its direction from +x (along a row) towards +y (down)
    double electronics_cutoff_hz = 0;  // electronics: 3 dB cutoff, Hz (needs dwell_s)
    double dwell_s = 0;                // dwell time per pixel along scan (x), seconds
    int poles = 1;                     // Butterworth order
    bool enabled = false;              // any --mtf-* option given

    // Throws UsageError naming the option for a value out of range, NaN or infinite.
    void check() const;
};

// Each term's MTF at one frequency (moduli) and their product.
struct MtfTerms {
    double optics = 1, detector = 1, motion = 1, electronics = 1, system = 1;
};

// The chain for one band: the parameters and the band's centre wavelength.
class MtfChain {
public:
    // wavelength_um is needed (> 0) only when the optics term is on.
    MtfChain(const MtfParams& params, double wavelength_um);

    // The optics cutoff in cycles/pixel (0 when the optics term is off).
    double optics_cutoff() const { return m_cutoff; }

    // The system transfer function at (νx, νy) cycles/pixel: real and even (zero phase),
    // signed where the motion term reverses contrast.
    double transfer(double nu_x, double nu_y) const;

    // Each term's MTF (modulus) at (νx, νy).
    MtfTerms terms(double nu_x, double nu_y) const;

private:
    MtfParams m_p;
    double m_cutoff = 0;
    double m_cos = 1, m_sin = 0;  // motion direction
};

// Filters one plane (rows x columns, row-major) by the chain's transfer function: the
// plane is mirrored (half-sample symmetric) to 2·rows x 2·columns, so the padded image
// is periodic without a seam (no wrap-around from the opposite border), transformed with
// FFTW's r2c, multiplied by transfer(νx, νy) and brought back with c2r; the top-left
// rows x columns are returned. Double precision throughout. Deterministic: FFTW_ESTIMATE
// plans (made and destroyed under a lock; FFTW's planner is not thread-safe), so the
// result is the same on every run and from any thread.
std::vector<float> apply_mtf(const std::vector<float>& plane, long rows, long columns,
                             const MtfChain& chain);

// One band's MTF at Nyquist along x (0.5 cycles/pixel, the scan direction) for -v.
struct MtfBandReport {
    double wavelength_um = 0;  // 0 when the cube has no wavelengths
    MtfTerms nyquist;
};

// sensorize's step: filters plane in place with the chain for a band centred at
// wavelength_um (0: unknown; then the optics term is a DataError naming cube_path).
MtfBandReport apply_band_mtf(std::vector<float>& plane, long rows, long columns,
                             const MtfParams& params, double wavelength_um,
                             const std::string& cube_path);

}  // namespace sigchain::sensor_response
