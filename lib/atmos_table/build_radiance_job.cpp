// The library behind tools/build_radiance (see build_radiance_job.hpp).
#include "atmos_table/build_radiance_job.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "atmos_table/tape7_radiance.hpp"
#include "core/data_dir.hpp"
#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "io/cdk.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"
#include "io/t7m.hpp"

namespace sigchain::atmos_table {

namespace {

// The sun, the column and what was assumed (--verbose).
void report_tables(const RadianceReport& report, const Reporter& reporter) {
    reporter.info("sun zenith " + format_number(report.sun_zenith_deg) + " deg, azimuth " +
                  format_number(report.sun_azimuth_deg) + " deg; Earth-Sun " +
                  format_number(report.earth_sun_distance_au) + " AU");
    reporter.info("ground " + format_number(report.ground_km) + " km, sensor " +
                  format_number(report.sensor_km) + " km, " + std::to_string(report.layers) +
                  " layers, visibility " + format_number(report.visibility_km) +
                  " km, view azimuth " + format_number(report.view_azimuth_deg) + " deg");
    char depth[32];
    std::snprintf(depth, sizeof depth, "%.3g", report.merge_tau);
    reporter.info("thin layers merged up to optical depth " + std::string(depth) +
                  (report.merge_rule.empty() ? "" : " (" + report.merge_rule + ")"));
    for (std::size_t b = 0; b < report.band_streams.size(); ++b) {
        const StreamChoice& c = report.band_streams[b];
        std::string line =
            "band " + std::to_string(b + 1) + ": " + std::to_string(c.streams) + " streams";
        if (c.check_streams > 0)
            line += " (auto: estimated error " + format_number(100 * c.estimated_error) +
                    " % against " + std::to_string(c.check_streams) + " streams at " +
                    std::to_string(c.probe_wavenumbers.size()) + " samples" +
                    (c.within_tolerance ? "" : "; above the tolerance: the largest candidate") +
                    ")";
        reporter.info(line);
        if (!c.within_tolerance)
            reporter.warn("band " + std::to_string(b + 1) +
                          ": no streams up to 32 meet --stream-tolerance (estimated error " +
                          format_number(100 * c.estimated_error) + " %): 32 used");
    }
    for (const auto& note : report.notes) reporter.info(note);
}

// --write-decks: every run's deck, then the run list (last, so that a list on disk
// names decks that are all there).
void write_decks(const BuildRadianceJob& job, const io::Cdk& deck, const io::Snd& snd,
                 const RadianceOptions& o, const Reporter& reporter) {
    const Tape7Decks decks = tape7_decks(deck, snd, o);
    const std::filesystem::path dir(job.write_decks_dir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw IoError("cannot create " + sigchain::quoted(dir.string()) + ": " + ec.message());
    for (const auto& [name, cdk] : decks.decks) {
        AtomicOutput out((dir / name).string());
        io::write_cdk(out.stream(), cdk);
        out.commit();
    }
    AtomicOutput list((dir / "runs.t7m").string());
    io::write_t7m(list.stream(), decks.list);
    list.commit();
    reporter.info("wrote " + std::to_string(decks.decks.size()) + " LOWTRAN 7 decks and " +
                  (dir / "runs.t7m").string());
}

// The run list of --from-tape7: the file, or runs.t7m in the directory.
std::string t7m_path(const std::string& given) {
    return std::filesystem::is_directory(given)
               ? (std::filesystem::path(given) / "runs.t7m").string()
               : given;
}

}  // namespace

void check_job(const BuildRadianceJob& job) {
    if (!job.write_decks_dir.empty() && !job.from_tape7.empty())
        throw UsageError("--write-decks and --from-tape7 cannot be given together");
    if (job.cdk_path == "-" && job.snd_path == "-")
        throw UsageError("only one input can be standard input");
    if (!(job.options.top_km > 0)) throw UsageError("--top must be > 0 km");
    if (job.options.merge_tau && !(*job.options.merge_tau >= 0 && *job.options.merge_tau <= 1))
        throw UsageError("--merge-tau must be in [0, 1]");
    check_radiance_options(job.options);
}

std::vector<std::string> band_output_paths(const std::string& pattern, const io::Snd& snd) {
    const int bands = static_cast<int>(snd.bands.size());
    std::vector<std::string> paths;
    for (int b = 1; b <= bands; ++b) paths.push_back(band_output_path(pattern, b, bands));
    if (bands > 1)
        for (const auto& p : paths)
            if (p == "-") throw UsageError("'-' names one band only");
    return paths;
}

void run(const BuildRadianceJob& job, const Reporter& job_reporter) {
    check_job(job);
    // MPI ranks other than 0 read the same inputs: only rank 0 reports and writes.
    const Reporter silent;
    const Reporter& reporter = farm_worker() ? silent : job_reporter;
    if (farm_available() && (job.cdk_path == "-" || job.snd_path == "-"))
        throw UsageError("standard input cannot be read under mpirun: every rank reads the inputs");
    const auto deck = io::read_cdk_file(job.cdk_path);
    const auto snd = io::read_snd_file(job.snd_path);
    const std::vector<std::string> paths = job.write_decks_dir.empty()
                                               ? band_output_paths(job.output_pattern, snd)
                                               : std::vector<std::string>{};
    std::vector<std::string> inputs{job.cdk_path, job.snd_path};
    if (!job.from_tape7.empty()) inputs.push_back(t7m_path(job.from_tape7));
    require_outputs_distinct(paths, inputs);
    RadianceOptions o = job.options;
    o.data_dir = data_dir(job.data_dir);
    o.snd_path = job.snd_path;
    o.cdk_path = job.cdk_path;

    if (!job.write_decks_dir.empty()) {
        if (farm_worker()) return;  // under mpirun rank 0 alone writes the decks
        return write_decks(job, deck, snd, o, reporter);
    }
    long total = 0;
    for (const auto& b : snd.bands) total += b.sample_count();
    const auto start = std::chrono::steady_clock::now();
    std::vector<io::Rad> rads;
    if (!job.from_tape7.empty()) {
        const std::string list = t7m_path(job.from_tape7);
        rads = tape7_radiance(io::read_t7m_file(list), list, deck, snd, o);
        reporter.info("tables from the TAPE7s of " + list);
    } else {
        RadianceReport report;
        rads = build_radiance(deck, snd, o, &report, reporter);
        if (farm_worker()) return;  // an MPI worker: rank 0 writes the tables
        report_tables(report, reporter);
    }
    if (farm_worker()) return;  // an MPI worker (or a TAPE7 run under mpirun): rank 0 writes
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The bands appear together or not at all (commit_together, sigchain(7) OUTPUTS).
    std::vector<std::unique_ptr<AtomicOutput>> outs;
    std::vector<AtomicOutput*> order;
    for (std::size_t b = 0; b < paths.size(); ++b) {
        outs.push_back(std::make_unique<AtomicOutput>(paths[b]));
        io::write_rad(outs.back()->stream(), rads[b]);
        order.push_back(outs.back().get());
    }
    commit_together(order);
    for (const auto& p : paths) reporter.info("wrote " + p);
    reporter.info(std::to_string(total) + " spectral samples in " + format_number(seconds) + " s");
}

}  // namespace sigchain::atmos_table
