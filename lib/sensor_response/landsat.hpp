// A Landsat scene as sigchain's sensor: each band's calibration from its MTL file (with the
// ETM+ gain states of Chander, Markham and Helder (2009)) and its relative spectral response
// on a wavenumber grid (man landsat_sensor(1)).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/report.hpp"
#include "io/mtl.hpp"
#include "io/snd.hpp"

namespace sigchain::sensor_response {

// ---- Calibration ------------------------------------------------------------------------

// ETM+ LMIN and LMAX (W m-2 sr-1 um-1) at low and high gain, QCAL 1 to 255: Chander, Markham
// and Helder (2009, Remote Sens. Environ. 113, 893-903), table 1 (products processed after
// 1 July 2000). nullopt for a band the table does not hold.
struct EtmGainRange {
    double lmin = 0, lmax = 0;
};
std::optional<EtmGainRange> etm_gain_range(const std::string& band, char gain_state);

// L = mult * QCAL + add, the table's rescaling: mult = (LMAX - LMIN) / (255 - 1),
// add = LMIN - mult.
struct Rescaling {
    double mult = 0;  // W m-2 sr-1 um-1 per DN, > 0
    double add = 0;   // W m-2 sr-1 um-1
};
Rescaling etm_table_rescaling(const EtmGainRange& range);

// One band's calibration as used.
struct BandCalibration {
    std::string name;      // "4"
    char gain_state = 0;   // 'H', 'L' or 0
    Rescaling rescaling;
    std::string source;    // "MTL", "table (low gain)", "table (high gain, --gain)"
    std::optional<double> qcal_min, qcal_max;
};

// Whether an MTL is an ETM+ file (gain states apply).
bool is_etm(const io::Mtl& mtl);

// "4=L,5=H" -> {4: 'L', 5: 'H'}; UsageError "--gain: ..." otherwise.
std::map<std::string, char> parse_gain_overrides(const std::string& text);

// The calibration of band `name`: a --gain override (ETM+ only) takes the table's values for
// that gain state; else the file's RADIANCE_MULT/ADD (warning, for ETM+, when they are not
// the table's for the stated gain state, within 1 %); else, for ETM+ with a gain state, the
// table's. nullopt when there is none. `mtl_path` names the file in warnings.
std::optional<BandCalibration> band_calibration(const io::Mtl& mtl, const std::string& name,
                                                const std::map<std::string, char>& overrides,
                                                const std::string& mtl_path,
                                                const Reporter& report);

// .sen gain and bias for the cube's radiance in W cm-2 sr-1 um-1: DN = (L - add) / mult with
// L in W m-2 sr-1 um-1 = 1e4 x the cube's, so gain = 1e4 / mult and bias = -add / mult.
double sen_gain(const Rescaling& r);
double sen_bias(const Rescaling& r);

// ---- Spectral sampling ------------------------------------------------------------------

// The default number of spectral samples per band (measured: landsat_sensor(1), SAMPLING).
inline constexpr int kDefaultSamples = 64;

struct SpectralOptions {
    int samples = kDefaultSamples;  // >= 2, used when increment_cm1 is 0
    double increment_cm1 = 0;       // > 0: a fixed step instead, the span rounded out to it
    double threshold = 0.001;       // fraction of the response's peak the span must cover
};

struct BandSpectrum {
    io::SndBand band;               // min, max, increment (cm-1)
    // One per spectral sample in the .rad's order (wavenumber decreasing, wavelength
    // increasing): the response's area over the sample's wavelength interval divided by
    // the sample's width as sensorize takes it (sample_widths_um).
    std::vector<double> response;
    double captured_fraction = 0;   // of the response's whole area (negatives as 0)
    double threshold_lo_nm = 0;     // the span above the threshold
    double threshold_hi_nm = 0;
};

// The wavenumber grid of a band and each sample's response, from a response tabulated at
// `wavelength_nm` (increasing; negative values taken as 0, the function linear between
// nodes and 0 outside). DataError-free: throws std::invalid_argument for a response with
// no positive value (callers name the file).
BandSpectrum band_spectrum(const std::vector<double>& wavelength_nm,
                           const std::vector<double>& response, const SpectralOptions& options);

// The integral of the response (negatives as 0, linear between nodes, 0 outside) from a_nm
// to b_nm, in nm.
double response_area_nm(const std::vector<double>& wavelength_nm,
                        const std::vector<double>& response, double a_nm, double b_nm);

}  // namespace sigchain::sensor_response
