// sensorize's command line (sensorize_command.hpp).
#include "commands/sensorize_command.hpp"

#include <cstdio>
#include <iostream>
#include <limits>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::commands {

namespace {

constexpr long double kInfinity = std::numeric_limits<long double>::infinity();

// "N" or "N,N,..." as numbers, for --target1/--target2.
std::vector<double> parse_targets(const std::string& text, const std::string& option) {
    std::vector<double> values;
    for (auto field : sigchain::split_fields(text, true))
        values.push_back(static_cast<double>(
            cli::parse_number(option, std::string(field), cli::reals(0, kInfinity))));
    if (values.empty()) throw sigchain::UsageError(option + ": expected counts");
    return values;
}

// "A" or "A,B" (or up to `most` numbers) for --mtf-smear and --mtf-electronics.
std::vector<double> parse_numbers(const std::string& text, const std::string& option,
                                  std::size_t least, std::size_t most, const char* form) {
    std::vector<double> values;
    try {
        for (auto field : sigchain::split_fields(text, true))
            values.push_back(sigchain::parse_double(field, {option, 0}, "a number"));
    } catch (const sigchain::DataError&) {
        values.clear();
    }
    if (values.size() < least || values.size() > most)
        throw sigchain::UsageError(option + ": expected " + form + ", found '" + text + "'");
    return values;
}

// The MTF chain's parameters from the --mtf-* options (sensorize(1), MTF).
sensor_response::MtfParams mtf_from(const cli::po::variables_map& vm) {
    sensor_response::MtfParams p;
    auto number = [&](const char* name, double& to) {
        if (!vm.count(name)) return;
        to = cli::real(vm, name);
        p.enabled = true;
    };
    number("mtf-fnumber", p.f_number);
    number("mtf-pitch", p.pitch_um);
    number("mtf-fill", p.fill_factor);
    number("mtf-defocus", p.defocus_sigma_px);
    if (vm.count("mtf-smear")) {
        const auto v = parse_numbers(vm["mtf-smear"].as<std::string>(), "--mtf-smear", 1, 2,
                                     "PX or PX,DEGREES");
        p.smear_px = v[0];
        if (v.size() > 1) p.smear_angle_deg = v[1];
        p.enabled = true;
    }
    if (vm.count("mtf-electronics")) {
        const auto v = parse_numbers(vm["mtf-electronics"].as<std::string>(), "--mtf-electronics",
                                     2, 3, "HZ,SECONDS or HZ,SECONDS,POLES");
        p.electronics_cutoff_hz = v[0];
        p.dwell_s = v[1];
        if (v.size() > 2) {
            if (v[2] != static_cast<int>(v[2]))
                throw sigchain::UsageError("--mtf-electronics: the number of poles must be 1 to 8");
            p.poles = static_cast<int>(v[2]);
        }
        // A cutoff of 0 would silently turn the term off: it must be positive.
        if (!(p.electronics_cutoff_hz > 0))
            throw sigchain::UsageError(
                "--mtf-electronics: the cutoff and the dwell time must be positive numbers");
        p.enabled = true;
    }
    if (p.enabled) p.check();
    return p;
}

// "0.62" or "1": an MTF value for the -v line, 3 significant digits.
std::string mtf_value(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace

void report_sensorize(const sensor_response::SensorizeReport& r, const sensor_response::SensorizeJob& job,
                      const cli::Context& ctx) {
    if (!r.cube_has_wavelengths)
        ctx.warn(job.cube_path + ": no wavelength list: spectral samples weighted equally");
    for (std::size_t b = 0; b < r.bands.size(); ++b) {
        const auto& band = r.bands[b];
        const std::string line = "band " + std::to_string(b + 1) + " (" + band.sen_path +
                                 "): " + std::to_string(band.clipped.low + band.clipped.high) +
                                 " of " + std::to_string(band.pixels) + " pixels clipped (" +
                                 std::to_string(band.clipped.low) + " low, " +
                                 std::to_string(band.clipped.high) + " high)";
        if (band.clipped.low + band.clipped.high > 0)
            ctx.warn(line);
        else
            ctx.info(line);
    }
    for (std::size_t b = 0; b < r.mtf.size(); ++b) {
        const auto& m = r.mtf[b];
        const auto& t = m.nyquist;
        ctx.info("band " + std::to_string(b + 1) + " (" +
                 (m.wavelength_um > 0 ? mtf_value(m.wavelength_um) + " um" : "no wavelength") +
                 "): MTF at Nyquist: optics " + mtf_value(t.optics) + ", detector " +
                 mtf_value(t.detector) + ", motion " + mtf_value(t.motion) + ", electronics " +
                 mtf_value(t.electronics) + ", system " + mtf_value(t.system));
    }
}

namespace {

// --seed, or its former name --noise-seed (with a warning); not both.
std::uint64_t noise_seed(const cli::po::variables_map& vm, const cli::Context& ctx) {
    if (!vm.count("noise-seed")) return cli::seed(vm);
    if (!vm["seed"].defaulted())
        throw sigchain::UsageError("give --seed or --noise-seed, not both");
    ctx.warn("--noise-seed is deprecated: use --seed");
    return static_cast<std::uint64_t>(
        cli::parse_number("--noise-seed", vm["noise-seed"].as<std::string>(), cli::seed_range()));
}

// --uncertainty-cube, or its former name --uncertainty (with a warning); not both.
// Empty when neither is given.
std::string uncertainty_cube(const cli::po::variables_map& vm, const cli::Context& ctx) {
    if (!vm.count("uncertainty"))
        return vm.count("uncertainty-cube") ? vm["uncertainty-cube"].as<std::string>() : "";
    if (vm.count("uncertainty-cube"))
        throw sigchain::UsageError("give --uncertainty-cube or --uncertainty, not both");
    ctx.warn("--uncertainty is deprecated: use --uncertainty-cube");
    return vm["uncertainty"].as<std::string>();
}

}  // namespace

sensor_response::SensorizeJob sensorize_job(const cli::po::variables_map& vm, const cli::Context& ctx) {
    auto inputs = cli::args(vm, "input");
    if (inputs.size() < 2) throw sigchain::UsageError("expected a cube and at least one .sen file");
    sensor_response::SensorizeJob job;
    job.cube_path = inputs[0];
    job.sen_paths.assign(inputs.begin() + 1, inputs.end());
    // Missing -o: check_job's usage error says what -o must name (image or directory).
    job.output_path = vm.count("output") ? cli::output_path(vm) : std::string();
    job.bits = static_cast<int>(cli::integer(vm, "bits"));
    job.float_output = vm.count("float") > 0;
    job.noise.seed = noise_seed(vm, ctx);
    if (vm.count("shot-noise")) job.noise.electrons_per_count = cli::real(vm, "shot-noise");
    if (vm.count("read-noise")) job.noise.read_noise_counts = cli::real(vm, "read-noise");
    if (vm.count("psf-sigma")) job.psf_sigma_px = cli::real(vm, "psf-sigma");
    if (vm.count("psf")) job.psf_path = vm["psf"].as<std::string>();
    job.mtf = mtf_from(vm);
    job.write_options = {cli::creation_options(vm), ctx.command()};
    if (vm.count("preview")) job.preview_path = vm["preview"].as<std::string>();
    if (vm.count("preview-stretch")) {
        const std::string s = vm["preview-stretch"].as<std::string>();
        if (s != "band" && s != "common")
            throw sigchain::UsageError("--preview-stretch " + s + ": expected band or common");
        if (job.preview_path.empty()) throw sigchain::UsageError("--preview-stretch needs --preview");
        job.preview_common = s == "common";
    }
    job.uncertainty_path = uncertainty_cube(vm, ctx);
    if (vm.count("uncertainty-output"))
        job.uncertainty_output_path = vm["uncertainty-output"].as<std::string>();
    job.calibrate = vm.count("calibrate") > 0;
    if (job.calibrate) {
        for (const char* o : {"card1", "card2", "target1", "target2"})
            if (!vm.count(o)) throw sigchain::UsageError(std::string("--calibrate needs --") + o);
        job.calibration.card1 = sensor_response::parse_box(vm["card1"].as<std::string>(), "--card1");
        job.calibration.card2 = sensor_response::parse_box(vm["card2"].as<std::string>(), "--card2");
        job.calibration.target1 = parse_targets(vm["target1"].as<std::string>(), "--target1");
        job.calibration.target2 = parse_targets(vm["target2"].as<std::string>(), "--target2");
    }
    return job;
}


cli::ToolInfo sensorize_info() {
    return {"sensorize",
            "Turn a radiance cube into the digital counts of a sensor: one channel per\n"
            ".sen band, in a GeoTIFF or PNG.",
            "[OPTIONS] CUBE SEN... -o IMAGE"};
}

void add_sensorize_options(cli::Cli& tool) {
    tool.add_positional("input", -1, "radiance cube (ENVI or GeoTIFF) and one .sen per band");
    using cli::po::value;
    tool.add_number("bits,b", "BITS", cli::integers(8, 16), "bits per count: 8, 12 or 16", "8");
    tool.add_number("shot-noise", "E", cli::positive(),
                    "photo-electrons per count E, > 0 (adds shot noise)");
    tool.add_number("read-noise", "SIGMA", cli::reals(0, kInfinity),
                    "read noise standard deviation, counts (>= 0)");
    tool.add_number("psf-sigma", "PX", cli::positive(),
                    "Gaussian point-spread function, sigma in pixels (> 0)");
    tool.add_number("mtf-fnumber", "N", cli::positive(1000),
                    "MTF: diffraction of a circular aperture of f-number N, > 0, <= 1000 "
                    "(needs --mtf-pitch)");
    tool.add_number("mtf-pitch", "UM", cli::positive(10000),
                    "MTF: detector pitch, micrometres (> 0, <= 10000)");
    tool.add_number("mtf-fill", "F", cli::reals(0, 1, true),
                    "MTF: detector width / pitch, 0 < F <= 1 (default 1)");
    tool.add_number("mtf-defocus", "PX", cli::reals(0, 10000),
                    "MTF: Gaussian defocus/aberration, sigma in pixels (0-10000)");
    tool.add_options()("float", "write band radiance unquantised (float TIFF) instead of counts")(
        "psf", value<std::string>()->value_name("FILE"), "point-spread function kernel file")(
        "mtf-smear", value<std::string>()->value_name("PX[,DEG]"),
        "MTF: image motion of PX pixels during integration, DEG from +x toward +y")(
        "mtf-electronics", value<std::string>()->value_name("HZ,S[,POLES]"),
        "MTF: Butterworth low-pass along scan: cutoff HZ, dwell S seconds per pixel")(
        "preview", value<std::string>()->value_name("PNG"),
        "also write a true-colour 8-bit PNG preview (2-98 % stretch)")(
        "preview-stretch", value<std::string>()->value_name("band|common"),
        "the preview's stretch: each band on its own (default), or one for all three")(
        "uncertainty-cube", value<std::string>()->value_name("TRUTH"),
        "trace's truth cube with uncertainty_BAND layers (trace --uncertainty)")(
        "uncertainty-output", value<std::string>()->value_name("FILE.tif"),
        "write the counts' standard uncertainty per band (with --uncertainty-cube)")(
        "calibrate", "solve gain and bias per band from two gray cards; -o names a directory")(
        "card1", value<std::string>()->value_name("BOX"), "card 1 pixel box ROW0,COL0,ROW1,COL1")(
        "card2", value<std::string>()->value_name("BOX"), "card 2 pixel box ROW0,COL0,ROW1,COL1")(
        "target1", value<std::string>()->value_name("COUNTS"),
        "card 1 target counts: C or C1,C2,...")(
        "target2", value<std::string>()->value_name("COUNTS"),
        "card 2 target counts: C or C1,C2,...");
    tool.add_creation_option();
    // Default 0, as --noise-seed had: an image with noise and no seed stays the same.
    tool.add_seed_option("seed of the noise (default 0)", 0);
    // The former name of --seed, still accepted (sensorize(1), DEPRECATED OPTIONS).
    tool.add_number("noise-seed", "N", cli::seed_range(), "use --seed", nullptr, true);
    // The former name of --uncertainty-cube, still accepted (sensorize(1), DEPRECATED
    // OPTIONS): in trace, --uncertainty reads an .unc file, so the cube got a name of its own.
    tool.add_hidden_options()("uncertainty", value<std::string>()->value_name("TRUTH"),
                              "use --uncertainty-cube");
    tool.add_required_output_option(
        "IMAGE",
        "the image to write (required); with --calibrate, the directory for the .sen files");
}

int run_sensorize_command(const cli::po::variables_map& vm, cli::Context& ctx) {
    const auto job = sensorize_job(vm, ctx);
    const auto result = sensor_response::run_sensorize(job);
    report_sensorize(result, job, ctx);
    if (job.calibrate) sensor_response::write_calibration_table(std::cout, result);
    return 0;
}

}  // namespace sigchain::commands
