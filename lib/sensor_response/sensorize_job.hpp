// The sensorize job: a radiance cube and one .sen per band -> a digital-count image, a
// band-radiance image (--float), or calibrated .sen files (--calibrate).
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "sensor_response/band.hpp"
#include "sensor_response/calibrate.hpp"
#include "sensor_response/mtf.hpp"
#include "sensor_response/noise.hpp"

namespace sigchain::sensor_response {

struct CalibrationSetup {
    PixelBox card1, card2;        // pixel boxes of the two gray cards in the cube
    std::vector<double> target1;  // target counts of card 1: one for all bands or one per band
    std::vector<double> target2;  // likewise for card 2
};

struct SensorizeJob {
    std::string cube_path;
    std::vector<std::string> sen_paths;  // one per sensor band, in band order
    std::string output_path;             // image (TIFF/PNG) or, with calibrate, a directory
    int bits = 8;                        // 8, 12 or 16
    bool float_output = false;           // write band radiance unquantised (float TIFF)
    NoiseModel noise;
    double psf_sigma_px = 0;  // Gaussian PSF when > 0
    std::string psf_path;     // kernel file (sensorize(1) PSF FILE) when not empty
    MtfParams mtf;            // the MTF chain (sensorize(1) MTF) when mtf.enabled
    bool calibrate = false;
    CalibrationSetup calibration;
    image::WriteOptions write_options;  // --co and the provenance of the image
    std::string preview_path;           // --preview: a true-colour PNG too, when not empty
    bool preview_common = false;        // --preview-stretch common: one stretch of band radiance
    // --uncertainty-cube TRUTH and --uncertainty-output FILE.tif (sensorize(1) UNCERTAINTY):
    // trace's uncertainty_BAND layers in, the counts' standard uncertainty out.
    std::string uncertainty_path;
    std::string uncertainty_output_path;
};

struct BandReport {
    std::string sen_path;
    std::size_t pixels = 0;
    ClipCount clipped;
};

struct CalibrationRow {
    std::string sen_path;                 // the input .sen
    std::string output_path;              // the updated .sen written
    double radiance1 = 0, radiance2 = 0;  // mean band radiance of the cards
    double count1 = 0, count2 = 0;        // their targets
    GainBias solved;
};

struct SensorizeReport {
    bool cube_has_wavelengths = true;  // false: samples weighted equally
    std::vector<BandReport> bands;     // counts mode: saturation per band
    std::vector<CalibrationRow> calibration;
    std::vector<MtfBandReport> mtf;  // with the MTF chain: each band's MTF at Nyquist
};

// Checks the job's options (bit depth, output name, calibration targets); throws
// UsageError. Called by run_sensorize before any file is read.
void check_job(const SensorizeJob& job);

// Runs the job and writes its output atomically. Throws DataError/IoError for bad
// inputs (a .sen whose sample count does not fit the cube names both files).
SensorizeReport run_sensorize(const SensorizeJob& job);

// The calibration table (stdout of --calibrate): a header line, then per band the .sen,
// the cards' band radiance, their targets, the solved gain and bias.
void write_calibration_table(std::ostream& out, const SensorizeReport& report);

}  // namespace sigchain::sensor_response
