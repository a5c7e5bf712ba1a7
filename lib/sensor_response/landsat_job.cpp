// landsat_sensor's Job (man landsat_sensor(1)): the MTL's calibration and the response
// tables into a .snd and one .sen per band, written as one set.
#include "sensor_response/landsat_job.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "core/error.hpp"
#include "core/output.hpp"
#include "geo/solar_position.hpp"
#include "io/rsr.hpp"
#include "io/sen.hpp"
#include "io/snd.hpp"

namespace sigchain::sensor_response {

namespace {

std::string base_name(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

// The response tables, loaded once each.
class Tables {
public:
    Tables(const LandsatJob& job, const io::Mtl& mtl) : m_job(job), m_mtl(mtl) {}
    // The table and column of band `name`; nullptr when no table has it.
    const io::RsrTable* find(const std::string& name, int& column, std::string& path) {
        for (const auto& p : paths_for(name)) {
            const io::RsrTable& t = load(p);
            column = io::rsr_column(t, name);
            if (column >= 0) return path = p, &t;
        }
        return nullptr;
    }

private:
    std::vector<std::string> paths_for(const std::string& name) const {
        if (!m_job.rsr_paths.empty()) return m_job.rsr_paths;
        const std::string dir = m_job.data_dir + "/spectra/";
        if (m_mtl.spacecraft == "LANDSAT_7") return {dir + "landsat7_etm_rsr.txt"};
        if (m_mtl.spacecraft == "LANDSAT_8")
            return {dir + (name == "10" || name == "11" ? "landsat8_tirs_rsr.txt"
                                                        : "landsat8_oli_rsr.txt")};
        throw DataError({m_job.mtl_path, 0}, "no response table of " + m_mtl.spacecraft +
                                                 " in the data directory; give --rsr FILE");
    }
    const io::RsrTable& load(const std::string& path) {
        auto& slot = m_loaded[path];
        if (!slot) slot = std::make_unique<io::RsrTable>(io::read_rsr_file(path));
        return *slot;
    }
    const LandsatJob& m_job;
    const io::Mtl& m_mtl;
    std::map<std::string, std::unique_ptr<io::RsrTable>> m_loaded;
};

bool default_band(const io::Mtl& mtl, const io::MtlBand& b) {
    const bool thermal_6 = mtl.spacecraft != "LANDSAT_8" && b.name.rfind("6", 0) == 0;  // TM, ETM+
    if (b.k1 || thermal_6 || b.name == "10" || b.name == "11") return false;
    if (b.name == "8") return false;                                  // panchromatic
    return !(mtl.spacecraft == "LANDSAT_8" && b.name == "9");         // cirrus
}

struct BandPlan {
    BandCalibration calibration;
    BandSpectrum spectrum;
    std::string rsr_path;
};

BandPlan plan_band(const LandsatJob& job, const io::Mtl& mtl, Tables& tables,
                   const std::string& name, const Reporter& report) {
    auto cal = band_calibration(mtl, name, job.gain_overrides, job.mtl_path, report);
    if (!cal)
        throw DataError({job.mtl_path, io::find_band(mtl, name) ? mtl.end_line : 0},
                        "band " + name + " has no radiance calibration (RADIANCE_MULT/ADD_BAND_" +
                            name + ", LMAX/LMIN, or an ETM+ gain state)");
    int column = -1;
    std::string path;
    const io::RsrTable* t = tables.find(name, column, path);
    if (!t)
        throw DataError({job.rsr_paths.empty() ? job.mtl_path : job.rsr_paths.front(), 0},
                        "no response column for band " + name + " (B" + name + ")");
    try {
        return {*cal, band_spectrum(t->wavelength_nm, t->response[column], job.spectral), path};
    } catch (const std::invalid_argument& e) {
        throw DataError({path, 0}, "column B" + name + ": " + e.what());
    }
}

io::Snd make_snd(const LandsatJob& job, const io::Mtl& mtl, const std::vector<BandPlan>& plans) {
    io::Snd snd;
    snd.sensor_altitude_km = job.altitude_km;
    for (const auto& p : plans) snd.bands.push_back(p.spectrum.band);
    snd.view_min_deg = job.view_min_deg, snd.view_max_deg = job.view_max_deg;
    snd.view_increment_deg = job.view_increment_deg;
    snd.year = mtl.year, snd.month = mtl.month, snd.day = mtl.day;
    snd.time_gmt_hours = mtl.time_gmt_hours;
    if (job.target_latitude_deg) {
        snd.latitude_deg = *job.target_latitude_deg;
        snd.longitude_east_deg = *job.target_longitude_east_deg;
    } else {
        for (const auto& c : mtl.corners)
            snd.latitude_deg += c.latitude_deg / 4, snd.longitude_east_deg += c.longitude_east_deg / 4;
        // To 1e-6 deg (0.1 m): the file keeps 5 decimals, the mean's last bits are noise.
        snd.latitude_deg = std::round(snd.latitude_deg * 1e6) / 1e6;
        snd.longitude_east_deg = std::round(snd.longitude_east_deg * 1e6) / 1e6;
    }
    // Informational (snd(5)): the zone of the target's mean solar time, GMT = local + offset.
    snd.gmt_offset_hours = -std::round(snd.longitude_east_deg / 15);
    snd.latitude_style = snd.longitude_style = io::CoordinateStyle::Hemisphere;
    return snd;
}

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

void summarise(const io::Mtl& mtl, const io::Snd& snd, const std::vector<BandPlan>& plans,
               const Reporter& report) {
    report.info("band gain mult(W/m2/sr/um/DN) add sen_gain sen_bias cm-1(min-max/inc) "
                "samples captured source");
    for (const auto& p : plans) {
        const auto& c = p.calibration;
        const auto& b = p.spectrum.band;
        report.info(c.name + " " + (c.gain_state ? std::string(1, c.gain_state) : "-") + " " +
                    format_number(c.rescaling.mult) + " " + format_number(c.rescaling.add) + " " +
                    fixed(sen_gain(c.rescaling), 2) + " " + fixed(sen_bias(c.rescaling), 4) + " " +
                    format_number(b.min_wavenumber_cm1) + "-" + format_number(b.max_wavenumber_cm1) +
                    "/" + format_number(b.increment_cm1) + " " + std::to_string(b.sample_count()) +
                    " " + fixed(100 * p.spectrum.captured_fraction, 3) + "% " + c.source);
    }
    const auto sun = geo::solar_position(io::scene_site(snd));
    auto mtl_angle = [](const std::optional<double>& v) { return v ? fixed(*v, 3) : "-"; };
    report.info("sun at " + fixed(snd.latitude_deg, 5) + "," + fixed(snd.longitude_east_deg, 5) +
                ": MTL elevation " + mtl_angle(mtl.sun_elevation_deg) + " azimuth " +
                mtl_angle(mtl.sun_azimuth_deg) + "; NREL SPA elevation " +
                fixed(90 - sun.zenith_deg, 3) + " azimuth " + fixed(sun.azimuth_deg, 3) + " deg");
}

void write_with_header(std::ostream& out, const std::vector<std::string>& header) {
    for (const auto& h : header) out << "# " << h << '\n';
}

}  // namespace

std::string landsat_output_name(const LandsatJob& job) {
    if (!job.name.empty()) return job.name;
    std::string n = base_name(job.mtl_path);
    for (const char* suffix : {"_MTL.txt", "_MTL.TXT", ".txt", ".mtl"}) {
        const std::string s = suffix;
        if (n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0)
            return n.substr(0, n.size() - s.size());
    }
    return n;
}

namespace {

// The bands to write: --bands, else the file's reflective bands with both a calibration
// and a response.
std::vector<std::string> chosen_bands(const LandsatJob& job, const io::Mtl& mtl, Tables& tables) {
    if (!job.bands.empty()) return job.bands;
    std::vector<std::string> out;
    for (const auto& b : mtl.bands) {
        int column = -1;
        std::string path;
        if (default_band(mtl, b) && band_calibration(mtl, b.name, job.gain_overrides, job.mtl_path, Reporter{}) &&
            tables.find(b.name, column, path))
            out.push_back(b.name);
    }
    if (out.empty()) throw DataError({job.mtl_path, 0}, "no reflective band with both a calibration and a response");
    return out;
}

}  // namespace

std::vector<std::string> landsat_bands(const LandsatJob& job) {
    const io::Mtl mtl = io::read_mtl_file(job.mtl_path);
    Tables tables(job, mtl);
    const auto bands = chosen_bands(job, mtl, tables);
    for (const auto& name : bands) plan_band(job, mtl, tables, name, Reporter{});  // its errors
    return bands;
}

void run_landsat_job(const LandsatJob& job, const Reporter& report) {
    const io::Mtl mtl = io::read_mtl_file(job.mtl_path);
    Tables tables(job, mtl);
    std::vector<BandPlan> plans;
    for (const auto& name : chosen_bands(job, mtl, tables))
        plans.push_back(plan_band(job, mtl, tables, name, report));
    const io::Snd snd = make_snd(job, mtl, plans);
    const std::string name = landsat_output_name(job);
    std::filesystem::create_directories(job.out_dir.empty() ? "." : job.out_dir);
    const std::string source = base_name(job.mtl_path);
    std::vector<std::unique_ptr<AtomicOutput>> outputs;
    for (const auto& p : plans) {
        const auto& c = p.calibration;
        outputs.push_back(std::make_unique<AtomicOutput>(job.out_dir + "/" + name + "-b" + c.name + ".sen"));
        write_with_header(outputs.back()->stream(), {
            name + "-b" + c.name + ".sen: " + mtl.spacecraft + " " + mtl.sensor + " band " + c.name +
                " from " + source + " and " + base_name(p.rsr_path) + " (landsat_sensor(1))",
            "gain state " + std::string(c.gain_state ? std::string(1, c.gain_state) : "none") +
                "; L = mult x DN + add, mult " + format_number(c.rescaling.mult) + ", add " +
                format_number(c.rescaling.add) + " W m-2 sr-1 um-1 (" + c.source + ")",
            "response: area of the RSR over each sample / the sample's width, wavelength increasing"});
        io::Sen sen{sen_gain(c.rescaling), sen_bias(c.rescaling), p.spectrum.response};
        io::write_sen(outputs.back()->stream(), sen);
    }
    outputs.push_back(std::make_unique<AtomicOutput>(job.out_dir + "/" + name + ".snd"));
    write_with_header(outputs.back()->stream(), {
        name + ".snd: " + mtl.spacecraft + " " + mtl.sensor + " from " + source + " (landsat_sensor(1))",
        "target " + std::string(job.target_latitude_deg ? "from --target" : "the mean of the four scene corners") +
            "; time: SCENE_CENTER_TIME; GMT offset: the target's mean solar time zone"});
    io::write_snd(outputs.back()->stream(), snd);
    if (report.verbose()) summarise(mtl, snd, plans, report);
    std::vector<AtomicOutput*> all;
    for (auto& o : outputs) all.push_back(o.get());
    commit_together(all);
}

}  // namespace sigchain::sensor_response
