// landsat_sensor's Job: one MTL file and response tables -> a .snd and one .sen per band
// (man landsat_sensor(1)).
#pragma once

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/report.hpp"
#include "sensor_response/landsat.hpp"

namespace sigchain::sensor_response {

struct LandsatJob {
    std::string mtl_path;
    std::vector<std::string> rsr_paths;  // searched in order; empty: the data directory's
    std::string data_dir;                // where spectra/landsat*_rsr.txt are (core/data_dir)
    std::vector<std::string> bands;      // empty: the default bands
    double altitude_km = 705;            // Landsat 7 and 8's orbit
    std::optional<double> target_latitude_deg, target_longitude_east_deg;  // both or neither
    double view_min_deg = -8, view_max_deg = 8, view_increment_deg = 1;
    std::string name;     // output base name; empty: the MTL's name without _MTL.txt
    std::string out_dir;  // DIR of DIR/NAME.snd and DIR/NAME-bK.sen
    SpectralOptions spectral;
    std::map<std::string, char> gain_overrides;
};

// The bands the job writes, in .snd order: the requested ones (each must have a calibration
// and a response, else DataError), or by default every band with both that is reflective and
// multispectral (no thermal, panchromatic or Landsat 8 cirrus band).
// Reads the MTL and the tables; writes nothing.
std::vector<std::string> landsat_bands(const LandsatJob& job);

// Writes DIR/NAME.snd and DIR/NAME-bK.sen as one set (commit_together), DIR made if needed;
// with a verbose reporter, the summary table (calibration, grid, captured area, the MTL's sun
// against the NREL SPA's) through report.info.
void run_landsat_job(const LandsatJob& job, const Reporter& report);

// The base name of the outputs: job.name, else the MTL's file name without "_MTL.txt" (or
// its extension).
std::string landsat_output_name(const LandsatJob& job);

}  // namespace sigchain::sensor_response
