// The trace job: option parsing and checks, and a run on tests/data/trace whose cube
// is checked against the path terms of the hand-written .rad files, interpolated here
// independently of Atmosphere::path.
#include "trace/trace_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "image/image.hpp"
#include "io/rad.hpp"

namespace sigchain::trace {
namespace {

// A Reporter that keeps what the job tells it.
struct Recorder final : Reporter {
    mutable std::vector<std::string> warnings, infos, finished;
    mutable std::vector<std::pair<long, long>> progress;  // "rendering" (done, total)
    void warn(const std::string& m) const override { warnings.push_back(m); }
    void info(const std::string& m) const override { infos.push_back(m); }
    void progress_update(const std::string& label, long done, long total) const override {
        if (label == "rendering") progress.emplace_back(done, total);
    }
    void progress_finish(const std::string& label) const override { finished.push_back(label); }
};

const std::string kData = SIGCHAIN_TEST_DATA "/trace/";
const std::string kGdb = SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb";

TraceJob box_job(const std::string& output) {
    TraceJob job;
    job.adv_path = kData + "box.adv";
    job.snd_path = kData + "box.snd";
    job.scene_path = kGdb;
    job.mat_path = kData + "box.mat";
    job.rad_paths = {kData + "band1.rad", kData + "band2.rad"};
    job.output_path = output;
    return job;
}

// A scratch directory removed afterwards.
struct Scratch {
    std::filesystem::path dir;
    Scratch() {
        dir =
            std::filesystem::temp_directory_path() /
            ("trace_job_test." + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "." + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir);
    }
    ~Scratch() { std::filesystem::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
};

TEST(TraceJob, ParsesSamplingNames) {
    EXPECT_EQ(parse_sampling("dirsig"), Sampling::Dirsig);
    EXPECT_EQ(parse_sampling("golfball"), Sampling::Golfball);
    EXPECT_EQ(parse_sampling("montecarlo"), Sampling::MonteCarlo);
    EXPECT_THROW(parse_sampling("Golfball"), UsageError);
    EXPECT_EQ(sampling_name(Sampling::MonteCarlo), "montecarlo");
}

TEST(TraceJob, ParsesRows) {
    EXPECT_EQ(parse_rows("0:16"), (std::pair<long, long>{0, 16}));
    EXPECT_EQ(parse_rows("5:6"), (std::pair<long, long>{5, 6}));
    for (const char* bad : {"", "5", "5:", ":5", "a:b", "-1:4", "3:3", "5:3", "1:2:3", "1.5:3"})
        EXPECT_THROW(parse_rows(bad), UsageError) << bad;
}

TEST(TraceJob, ChecksOptionsBeforeReadingFiles) {
    auto job = box_job("out.img");
    EXPECT_NO_THROW(check_job(job));
    job.output_path = "-";
    EXPECT_THROW(check_job(job), UsageError);
    job.output_path = "out.png";
    EXPECT_THROW(check_job(job), UsageError);
    job = box_job("out.img");
    job.truth_path = "out.hdr";  // the same ENVI file as out.img
    EXPECT_THROW(check_job(job), UsageError);
    job = box_job("out.img");
    job.samples_per_pixel = 0;
    EXPECT_THROW(check_job(job), UsageError);
    job = box_job("out.img");
    job.rad_paths.clear();
    EXPECT_THROW(check_job(job), UsageError);
}

TEST(TraceJob, RefusesRowsPastTheImageAndARadCountOffTheSnd) {
    Scratch s;
    auto job = box_job(s.file("out.img"));
    job.rows = std::pair<long, long>{0, 17};
    EXPECT_THROW(run_trace(job, Reporter{}), UsageError);
    job = box_job(s.file("out.img"));
    job.rad_paths.pop_back();
    EXPECT_THROW(run_trace(job, Reporter{}), UsageError);
    EXPECT_FALSE(std::filesystem::exists(s.file("out.img")));
}

// tau2 and L_us of `rad` at sample k and view angle `va`, linear between the table's
// view angles (the independent reference for the job's wiring of the path terms).
void path_terms(const io::Rad& rad, std::size_t k, double va, double& tau2, double& lus) {
    const auto& v = rad.views;
    std::size_t i = 0;
    while (i + 2 < v.size() && va > v[i + 1].view_angle_deg) ++i;
    double f = (va - v[i].view_angle_deg) / (v[i + 1].view_angle_deg - v[i].view_angle_deg);
    f = std::clamp(f, 0.0, 1.0);
    tau2 = (1 - f) * v[i].path[k].transmission + f * v[i + 1].path[k].transmission;
    lus = (1 - f) * v[i].path[k].scattered_radiance + f * v[i + 1].path[k].scattered_radiance;
}

// At the band-centre samples the cube is solar + downwelled + L_us (the truth's solar
// and downwelled layers are at the sensor, through tau2), with tau2 and L_us from the
// .rad at the truth layer's view angle: checks that the job hands the
// renderer the .rad files in band order and the truth cube its layer names.
TEST(TraceJob, CubeIsTheLeavingRadianceThroughTheRadPathTerms) {
    Scratch s;
    auto job = box_job(s.file("out.img"));
    job.truth_path = s.file("truth.tif");
    job.samples_per_pixel = 1;  // truth layers describe the one sample of each pixel
    Recorder recorder;
    const TraceReport report = run_trace(job, recorder);
    const std::vector<std::string>& infos = recorder.infos;
    // The render's progress reaches its 16 rows, and its line is ended.
    ASSERT_FALSE(recorder.progress.empty());
    EXPECT_EQ(recorder.progress.back(), std::make_pair(16L, 16L));
    EXPECT_EQ(recorder.finished, std::vector<std::string>{"rendering"});
    EXPECT_EQ(report.rows, 16);
    EXPECT_EQ(report.columns, 16);
    EXPECT_EQ(report.spectral_samples, 6u);
    EXPECT_EQ(report.bands, 2u);
    EXPECT_EQ(report.load.facets, 6u);
    EXPECT_EQ(report.stats.primary_rays, 256u);
    EXPECT_NE(std::find_if(infos.begin(), infos.end(),
                           [](const std::string& m) {
                               return m.find("emission is left out") != std::string::npos;
                           }),
              infos.end());

    const image::Image cube = image::read_image(s.file("out.img"));
    const image::Image truth = image::read_image(s.file("truth.tif"));
    ASSERT_EQ(cube.channels, 6);
    ASSERT_EQ(cube.wavelength_um.size(), 6u);
    EXPECT_NEAR(cube.wavelength_um[0], 0.5, 1e-6);
    EXPECT_NEAR(cube.wavelength_um[3], 0.625, 1e-6);
    EXPECT_EQ(cube.units, "W cm-2 sr-1 um-1");
    auto layer = [&](const std::string& name) {
        for (int c = 0; c < truth.channels; ++c)
            if (truth.channel_names[c] == name) return c;
        ADD_FAILURE() << "no truth layer " << name;
        return 0;
    };
    const io::Rad rads[2] = {io::read_rad_file(job.rad_paths[0]),
                             io::read_rad_file(job.rad_paths[1])};
    const int centre_channel[2] = {1, 4};  // middle sample of each 3-sample band
    int hits = 0;
    for (long r = 0; r < 16; ++r)
        for (long x = 0; x < 16; ++x) {
            if (truth.at(layer("hit"), r, x) < 1) continue;
            ++hits;
            const double va = truth.at(layer("view_angle_deg"), r, x);
            for (int b = 0; b < 2; ++b) {
                const std::string band = b == 0 ? "band1" : "band2";
                double tau2 = 0, lus = 0;
                path_terms(rads[b], 1, va, tau2, lus);
                // float32 layers: 1e-6 is about 10 float ulps of values near 1 and 1e-6
                // relative a few ulps of L_us; the cube sum of three float32 terms
                // carries about 3 ulps, 1e-5 relative is safely above that.
                EXPECT_NEAR(truth.at(layer("transmission_" + band), r, x), tau2, 1e-6);
                EXPECT_NEAR(truth.at(layer("upwelled_" + band), r, x), lus, 1e-6 * lus + 1e-12);
                const double want = truth.at(layer("solar_" + band), r, x) +
                                    truth.at(layer("downwelled_" + band), r, x) + lus;
                EXPECT_NEAR(cube.at(centre_channel[b], r, x), want, 1e-5 * want)
                    << "pixel " << r << "," << x << " " << band;
            }
        }
    EXPECT_GT(hits, 200);  // the ground fills all but the top row
}

TEST(TraceJob, AllowDegenerateWarnsThroughTheReporter) {
    Scratch s;
    auto job = box_job(s.file("out.tif"));
    job.scene_path = kData + "degenerate.gdb";
    EXPECT_THROW(run_trace(job, Reporter{}), DataError);
    job.allow_degenerate = true;
    Recorder recorder;
    run_trace(job, recorder);
    const std::vector<std::string>& warnings = recorder.warnings;
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("(2-1-1)"), std::string::npos) << warnings[0];
    EXPECT_TRUE(std::filesystem::exists(s.file("out.tif")));
}

}  // namespace
}  // namespace sigchain::trace
