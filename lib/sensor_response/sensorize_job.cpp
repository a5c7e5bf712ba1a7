// The sensorize job (White (1996), section 4.2.3.10, 4.2.4): cube + .sen files -> counts, radiance or gains.
#include "sensor_response/sensorize_job.hpp"

#include <cctype>
#include <filesystem>
#include <memory>
#include <set>

#include "core/error.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "image/geolocation.hpp"
#include "image/image.hpp"
#include "io/sen.hpp"
#include "sensor_response/count_uncertainty.hpp"
#include "sensor_response/psf.hpp"

namespace sigchain::sensor_response {
namespace {

std::string stem_of(const std::string& path) {
    return path == "-" ? std::string("stdin") : std::filesystem::path(path).stem().string();
}

// The cube's wavelengths for one band's samples (empty when the cube has none).
std::vector<double> band_wavelengths(const image::Image& cube, BandSamples s) {
    if (cube.wavelength_um.empty()) return {};
    return {cube.wavelength_um.begin() + s.first, cube.wavelength_um.begin() + s.first + s.count};
}

double target_for(const std::vector<double>& targets, std::size_t band) {
    return targets.size() == 1 ? targets[0] : targets[band];
}

void calibrate_band(const SensorizeJob& job, std::size_t b, const std::vector<float>& radiance,
                    const image::Image& cube, SensorizeReport& report) {
    CalibrationRow row;
    row.sen_path = job.sen_paths[b];
    row.radiance1 = box_mean(radiance, cube.rows, cube.columns, job.calibration.card1, "--card1");
    row.radiance2 = box_mean(radiance, cube.rows, cube.columns, job.calibration.card2, "--card2");
    row.count1 = target_for(job.calibration.target1, b);
    row.count2 = target_for(job.calibration.target2, b);
    row.solved =
        solve_gain_bias(row.radiance1, row.count1, row.radiance2, row.count2, row.sen_path);
    row.output_path =
        (std::filesystem::path(job.output_path) / (stem_of(row.sen_path) + ".sen")).string();
    report.calibration.push_back(row);
}

void write_calibrated_sens(const std::vector<io::Sen>& sens, const SensorizeReport& report) {
    // All bands are solved before any file is written: a failure leaves no partial set.
    // The bands' files appear together (commit_together, sigchain(7) OUTPUTS).
    std::vector<std::unique_ptr<AtomicOutput>> outs;
    std::vector<AtomicOutput*> order;
    for (std::size_t b = 0; b < sens.size(); ++b) {
        io::Sen updated = sens[b];
        updated.gain = report.calibration[b].solved.gain;
        updated.bias = report.calibration[b].solved.bias;
        outs.push_back(std::make_unique<AtomicOutput>(report.calibration[b].output_path));
        io::write_sen(outs.back()->stream(), updated);
        order.push_back(outs.back().get());
    }
    commit_together(order);
}

// No output may overwrite an input: with --calibrate the .sen files it writes into -o DIR,
// otherwise the image, the preview and the uncertainty cube.
void check_outputs_distinct(const SensorizeJob& job) {
    std::vector<std::string> inputs = job.sen_paths;
    inputs.push_back(job.cube_path);
    inputs.push_back(job.psf_path);
    inputs.push_back(job.uncertainty_path);
    if (job.calibrate) {
        std::vector<std::string> outputs;
        for (const auto& path : job.sen_paths)
            outputs.push_back(
                (std::filesystem::path(job.output_path) / (stem_of(path) + ".sen")).string());
        require_outputs_distinct(outputs, inputs);
    } else {
        require_outputs_distinct({job.output_path, job.preview_path, job.uncertainty_output_path},
                                 inputs);
    }
}

// --calibrate's options: one target count or one per band, .sen files of distinct names,
// -o a directory.
void check_calibration(const SensorizeJob& job) {
    if (job.float_output) throw UsageError("give --calibrate or --float, not both");
    const auto& c = job.calibration;
    for (const auto* t : {&c.target1, &c.target2})
        if (t->size() != 1 && t->size() != job.sen_paths.size())
            throw UsageError("--target1 and --target2 take one count or one per band (" +
                             std::to_string(job.sen_paths.size()) + ")");
    std::set<std::string> names;
    for (const auto& path : job.sen_paths)
        if (!names.insert(stem_of(path)).second)
            throw UsageError("--calibrate: two .sen files named " + stem_of(path) +
                             ".sen would be written to the same file");
    if (!std::filesystem::is_directory(job.output_path))
        throw UsageError("-o " + job.output_path +
                         ": not a directory (--calibrate writes "
                         "one .sen per band there)");
}

// The image's format: a .tif with --float, otherwise .tif, .png, .pgm or .ppm.
void check_output_format(const SensorizeJob& job) {
    const std::string ext = file_extension(job.output_path);
    const bool tiff = ext == "tif" || ext == "tiff";
    const bool counts_ok = tiff || ext == "png" || ext == "pgm" || ext == "ppm";
    if (job.float_output ? !tiff : !counts_ok)
        throw UsageError("-o " + job.output_path + ": the output must be a " +
                         (job.float_output ? ".tif" : ".tif, .png, .pgm or .ppm") + " file");
}

}  // namespace

void check_job(const SensorizeJob& job) {
    if (job.sen_paths.empty()) throw UsageError("expected a cube and at least one .sen file");
    if (job.bits != 8 && job.bits != 12 && job.bits != 16)
        throw UsageError("--bits must be 8, 12 or 16");
    if (job.psf_sigma_px > 0 && !job.psf_path.empty())
        throw UsageError("give --psf-sigma or --psf, not both");
    if (job.psf_sigma_px < 0) throw UsageError("--psf-sigma must be positive");
    if (job.mtf.enabled) job.mtf.check();
    if (job.noise.electrons_per_count < 0) throw UsageError("--shot-noise must be positive");
    if (job.noise.read_noise_counts < 0) throw UsageError("--read-noise must not be negative");
    if (job.output_path.empty() || job.output_path == "-")
        throw UsageError(job.calibrate ? "--calibrate needs -o DIR for the updated .sen files"
                                       : "an image cannot go to standard output: give -o FILE");
    image::check_write_options(job.calibrate ? std::string("-") : job.output_path,
                               job.write_options);
    if (!job.preview_path.empty() &&
        (job.calibrate || file_extension(job.preview_path) != "png"))
        throw UsageError("--preview " + job.preview_path +
                         ": the preview is a .png file, not made with --calibrate");
    if (job.uncertainty_path.empty() != job.uncertainty_output_path.empty())
        throw UsageError("--uncertainty-cube and --uncertainty-output go together");
    if (!job.uncertainty_path.empty() &&
        (job.calibrate || file_extension(job.uncertainty_output_path) != "tif"))
        throw UsageError("--uncertainty-output " + job.uncertainty_output_path +
                         ": a float .tif file, not made with --calibrate");
    check_outputs_distinct(job);
    if (job.calibrate) {
        check_calibration(job);
        return;
    }
    check_output_format(job);
}

namespace {

// The cube's georeferencing on a GeoTIFF output (cube(5), Georeferencing): the CRS and
// geotransform as they are (the image grid is the cube's); geolocation arrays copied
// beside the output (NAME.geoloc.tif, committed with it), which then names its own
// copy; the ground control points as they are. PNG and Netpbm outputs carry none.
void carry_georeference(const SensorizeJob& job, const image::Image& cube, image::Image& out) {
    const std::string ext = file_extension(job.output_path);
    if (ext != "tif" && ext != "tiff") return;
    out.georef = cube.georef;
    if (cube.georef.geolocation_path.empty()) return;
    out.georef.geolocation_path = image::geolocation_name(job.output_path);
    out.georef.arrays = std::make_shared<const image::GeolocationArrays>(
        image::read_geolocation(cube.georef.geolocation_path));
}

// The counts' (or with --float the band radiance's) standard uncertainty, one float
// band per sensor band, named and georeferenced as the output.
void write_uncertainty(const SensorizeJob& job, const image::Image& out,
                       const std::vector<std::vector<float>>& sigma) {
    image::Image u(out.rows, out.columns, static_cast<int>(sigma.size()));
    u.units = out.units;
    u.channel_names = out.channel_names;
    u.wavelength_um = out.wavelength_um;
    u.fwhm_um = out.fwhm_um;
    u.georef = out.georef;  // the ground control points place it; no arrays of its own
    u.georef.geolocation_path.clear();
    u.georef.arrays.reset();
    for (std::size_t b = 0; b < sigma.size(); ++b)
        std::copy(sigma[b].begin(), sigma[b].end(), u.data.begin() + b * u.plane_size());
    image::write_float(job.uncertainty_output_path, u, job.write_options);
}

// The inputs: the .sen files, the cube, the cube's samples of each band and the PSF.
struct Inputs {
    std::vector<io::Sen> sens;
    image::Image cube;
    std::vector<BandSamples> groups;
    Kernel kernel;
    bool blur = false;
};

// What the bands make: the output image, the band radiance for the preview
// (--preview-stretch common) and the uncertainty (--uncertainty-cube: per band, radiance
// then counts).
struct Products {
    image::Image out;
    image::Image radiance;
    std::vector<std::vector<float>> sigma;
};

Inputs read_inputs(const SensorizeJob& job) {
    Inputs in;
    for (const auto& path : job.sen_paths) in.sens.push_back(io::read_sen_file(path));
    in.cube = image::read_image(job.cube_path);
    in.groups = group_bands(in.sens, job.sen_paths, in.cube.channels, job.cube_path);
    in.blur = job.psf_sigma_px > 0 || !job.psf_path.empty();
    if (job.psf_sigma_px > 0) in.kernel = gaussian_kernel(job.psf_sigma_px);
    if (!job.psf_path.empty()) in.kernel = read_kernel_file(job.psf_path);
    return in;
}

// The radiance's standard uncertainty per band (--uncertainty-cube; none without it), in
// the .sen's unit unless --float.
std::vector<std::vector<float>> read_sigma(const SensorizeJob& job, const image::Image& cube,
                                           int bands, double to_sen_units) {
    std::vector<std::vector<float>> sigma;
    if (!job.uncertainty_path.empty())
        sigma = read_radiance_uncertainty(job.uncertainty_path, cube, bands);
    if (!job.float_output && to_sen_units != 1)
        for (auto& s : sigma)
            for (float& v : s) v *= static_cast<float>(to_sen_units);
    return sigma;
}

// Band b: its radiance through the .sen's response; with --calibrate its gain and bias
// solved, otherwise blurred, its MTF applied and (unless --float) made counts, then stored
// as the output's band b with its name, centre wavelength and width.
void sensorize_band(const SensorizeJob& job, const Inputs& in, int b, double to_sen_units,
                    bool radiance_preview, Products& p, SensorizeReport& report) {
    const image::Image& cube = in.cube;
    const std::vector<io::Sen>& sens = in.sens;
    image::Image& out = p.out;
    const auto wavelengths = band_wavelengths(cube, in.groups[b]);
    const auto widths = sample_widths_um(wavelengths, in.groups[b].count);
    std::vector<float> plane =
        band_radiance(cube, in.groups[b], sens[b].response, widths, job.sen_paths[b]);
    // Counts and calibration take the .sen's unit, W cm-2 sr-1 um-1.
    if (!job.float_output && to_sen_units != 1)
        for (float& v : plane) v *= static_cast<float>(to_sen_units);
    if (job.calibrate) {
        calibrate_band(job, b, plane, cube, report);
        return;
    }
    if (in.blur) plane = convolve(plane, cube.rows, cube.columns, in.kernel);
    if (job.mtf.enabled) {
        const double centre_um =
            wavelengths.empty() ? 0 : centre_wavelength_um(wavelengths, sens[b].response, widths);
        report.mtf.push_back(
            apply_band_mtf(plane, cube.rows, cube.columns, job.mtf, centre_um, job.cube_path));
    }
    if (radiance_preview)
        std::copy(plane.begin(), plane.end(),
                  p.radiance.data.begin() + b * p.radiance.plane_size());
    if (!job.float_output) {
        apply_gain_bias(plane, sens[b].gain, sens[b].bias);
        if (!p.sigma.empty())
            counts_uncertainty(p.sigma[b], plane, sens[b].gain, sens[b].bias, job.noise);
        add_noise(plane, sens[b].bias, job.noise, static_cast<std::uint64_t>(b));
        // c = gain L + bias back to the band radiance L (GDAL scale and offset).
        out.scale.push_back(1.0 / sens[b].gain);
        out.offset.push_back(0.0 - sens[b].bias / sens[b].gain);  // not -0
        report.bands.push_back({job.sen_paths[b], plane.size(), quantise(plane, job.bits)});
    }
    std::copy(plane.begin(), plane.end(), out.data.begin() + b * out.plane_size());
    out.channel_names.push_back(stem_of(job.sen_paths[b]));
    if (wavelengths.empty()) return;
    out.wavelength_um.push_back(centre_wavelength_um(wavelengths, sens[b].response, widths));
    out.fwhm_um.push_back(fwhm_um(wavelengths, sens[b].response));
}

// The updated .sen files (--calibrate) or the image, then the preview and the uncertainty.
void write_outputs(const SensorizeJob& job, const Inputs& in, bool radiance_preview,
                   Products& p, const SensorizeReport& report) {
    image::Image& out = p.out;
    // The preview is made first: a cube it cannot show then leaves no output.
    p.radiance.wavelength_um = out.wavelength_um;
    const image::Image preview =
        job.preview_path.empty()
            ? image::Image()
            : image::true_colour_preview(radiance_preview ? p.radiance : out, job.preview_path,
                                         job.preview_common);
    if (!job.calibrate) carry_georeference(job, in.cube, out);
    if (job.calibrate)
        write_calibrated_sens(in.sens, report);
    else if (job.float_output)
        image::write_float(job.output_path, out, job.write_options);
    else
        image::write_counts(job.output_path, out, job.bits, job.write_options);
    if (!job.preview_path.empty())
        image::write_counts(job.preview_path, preview, 8);
    if (!p.sigma.empty()) write_uncertainty(job, out, p.sigma);
}

}  // namespace

SensorizeReport run_sensorize(const SensorizeJob& job) {
    check_job(job);
    const Inputs in = read_inputs(job);
    const image::Image& cube = in.cube;
    SensorizeReport report;
    report.cube_has_wavelengths = !cube.wavelength_um.empty();
    const int bands = static_cast<int>(in.sens.size());
    Products p;
    p.out = image::Image(cube.rows, cube.columns, bands);
    p.out.units = job.float_output ? cube.units : "DC";
    if (!job.float_output) p.out.scaled_units = "W cm-2 sr-1 um-1";  // the .sen gain's unit
    // --preview-stretch common: the preview of the band radiance, not of counts whose
    // gains differ from band to band.
    const bool radiance_preview = job.preview_common && !job.float_output;
    p.radiance = image::Image(radiance_preview ? cube.rows : 0, cube.columns, bands);
    // A cube in W m-2 sr-1 um-1 (trace --radiance-units W/m2/sr/um) to the .sen's unit.
    const double to_sen_units = cube.units == "W m-2 sr-1 um-1" ? 1e-4 : 1.0;
    p.sigma = read_sigma(job, cube, bands, to_sen_units);
    for (int b = 0; b < bands; ++b)
        sensorize_band(job, in, b, to_sen_units, radiance_preview, p, report);
    write_outputs(job, in, radiance_preview, p, report);
    return report;
}

void write_calibration_table(std::ostream& out, const SensorizeReport& report) {
    out << "# sen radiance1 radiance2 count1 count2 gain bias\n";
    for (const auto& row : report.calibration)
        out << row.sen_path << ' ' << format_number(row.radiance1) << ' '
            << format_number(row.radiance2) << ' ' << format_number(row.count1) << ' '
            << format_number(row.count2) << ' ' << format_number(row.solved.gain) << ' '
            << format_number(row.solved.bias) << '\n';
}

}  // namespace sigchain::sensor_response
