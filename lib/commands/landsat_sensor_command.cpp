// landsat_sensor's command line (landsat_sensor_command.hpp).
#include "commands/landsat_sensor_command.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "core/data_dir.hpp"
#include "core/error.hpp"

namespace sigchain::commands {

namespace {

// "1,2,3" as band names; UsageError naming `option` for an empty one.
std::vector<std::string> split_list(const std::string& text, const char* option) {
    std::vector<std::string> out;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t comma = text.find(',', pos);
        if (comma == std::string::npos) comma = text.size();
        out.push_back(text.substr(pos, comma - pos));
        if (out.back().empty())
            throw sigchain::UsageError(std::string(option) + ": " + text + ": empty band name");
        pos = comma + 1;
    }
    return out;
}

// --target LAT,LON into the Job.
void read_target(const cli::po::variables_map& vm, sensor_response::LandsatJob& job) {
    if (!vm.count("target")) return;
    const auto v = cli::parse_number_list("--target", vm["target"].as<std::string>(),
                                          {cli::reals(-90, 90), cli::reals(-180, 180)}, "LAT,LON");
    job.target_latitude_deg = static_cast<double>(v[0]);
    job.target_longitude_east_deg = static_cast<double>(v[1]);
}

// --view-angles MIN,MAX,INC into the Job.
void read_view_angles(const cli::po::variables_map& vm, sensor_response::LandsatJob& job) {
    const auto view = cli::parse_number_list(
        "--view-angles", vm["view-angles"].as<std::string>(),
        {cli::reals(-90, 90), cli::reals(-90, 90), cli::positive(180)}, "MIN,MAX,INC");
    if (view[1] < view[0]) throw sigchain::UsageError("--view-angles: MAX below MIN");
    job.view_min_deg = static_cast<double>(view[0]);
    job.view_max_deg = static_cast<double>(view[1]);
    job.view_increment_deg = static_cast<double>(view[2]);
}

}  // namespace

cli::ToolInfo landsat_sensor_info() {
    return {"landsat_sensor",
            "Turn a Landsat MTL metadata file and relative spectral responses into the\n"
            "scene node (.snd) and one sensor band file (.sen) per band.",
            "[OPTIONS] MTL -o DIR | --print-bands MTL"};
}

void add_landsat_sensor_options(cli::Cli& tool) {
    using cli::po::value;
    tool.add_positional("mtl", 1, "the Landsat MTL metadata file");
    tool.add_options()(
        "rsr", value<std::vector<std::string>>()->value_name("FILE"),
        "response table (rsr(5)), repeatable, searched in order (default: the data directory's "
        "table for the spacecraft)")(
        "data-dir", value<std::string>()->value_name("DIR"),
        "the data directory (default: SIGCHAIN_DATA or the installed or source data/)")(
        "bands", value<std::string>()->value_name("LIST"),
        "bands to write, e.g. 1,2,3,4,5,7 (default: the reflective multispectral bands)")(
        "target", value<std::string>()->value_name("LAT,LON"),
        "target latitude and longitude, east positive (default: the mean of the four corners)")(
        "view-angles", value<std::string>()->default_value("-8,8,1")->value_name("MIN,MAX,INC"),
        "view-angle line of the .snd (deg)")(
        "name", value<std::string>()->value_name("NAME"),
        "base name of the outputs (default: the MTL's name without _MTL.txt)")(
        "gain", value<std::string>()->value_name("BAND=H|L[,...]"),
        "ETM+ gain state per band, overriding the file's (rescaling from Chander et al. 2009)")(
        "print-bands", "print the bands that would be written (comma-separated) and exit");
    tool.add_number("altitude", "KM", cli::reals(-0.5, 1000), "sensor altitude (km, -0.5 to 1000)",
                    "705");
    tool.add_number("samples", "N", cli::integers(2, 100000),
                    "spectral samples per band (2 to 100000)", "64");
    tool.add_number("increment", "CM1", cli::positive(10000),
                    "a fixed wavenumber step instead of --samples (cm-1, > 0)");
    tool.add_number("threshold", "X", cli::reals(0, 1, true),
                    "fraction of the response's peak the band's span covers (> 0 to 1)", "0.001");
    tool.add_required_output_option("DIR", "write DIR/NAME.snd and DIR/NAME-bK.sen; required");
}

sensor_response::LandsatJob landsat_sensor_job(const cli::po::variables_map& vm) {
    sensor_response::LandsatJob job;
    job.mtl_path = cli::args(vm, "mtl").at(0);
    if (vm.count("rsr")) job.rsr_paths = vm["rsr"].as<std::vector<std::string>>();
    if (job.rsr_paths.empty())
        job.data_dir =
            sigchain::data_dir(vm.count("data-dir") ? vm["data-dir"].as<std::string>() : "");
    if (vm.count("bands")) job.bands = split_list(vm["bands"].as<std::string>(), "--bands");
    job.altitude_km = cli::real(vm, "altitude");
    read_target(vm, job);
    read_view_angles(vm, job);
    if (vm.count("name")) job.name = vm["name"].as<std::string>();
    job.spectral.samples = static_cast<int>(cli::integer(vm, "samples"));
    if (vm.count("increment")) job.spectral.increment_cm1 = cli::real(vm, "increment");
    job.spectral.threshold = cli::real(vm, "threshold");
    if (vm.count("gain"))
        job.gain_overrides = sensor_response::parse_gain_overrides(vm["gain"].as<std::string>());
    if (!vm.count("print-bands")) job.out_dir = cli::output_path(vm);
    return job;
}

int run_landsat_sensor_command(const cli::po::variables_map& vm, cli::Context& ctx) {
    const auto job = landsat_sensor_job(vm);
    if (vm.count("print-bands")) {
        const auto bands = sensor_response::landsat_bands(job);
        for (std::size_t i = 0; i < bands.size(); ++i) std::cout << (i ? "," : "") << bands[i];
        std::cout << '\n';
        return 0;
    }
    sensor_response::run_landsat_job(job, ctx);
    return 0;
}

}  // namespace sigchain::commands
