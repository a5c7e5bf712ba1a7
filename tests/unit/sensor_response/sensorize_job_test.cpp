// Tests for the sensorize job (lib/sensor_response/sensorize_job): calibration and outputs.
#include "sensor_response/sensorize_job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "image/image.hpp"
#include "io/sen.hpp"

using namespace sigchain;
using namespace sigchain::sensor_response;

namespace {

class JobFiles : public ::testing::Test {
protected:
    std::filesystem::path dir;
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              (std::string("sigchain_sensorize_job_") +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir / "out");
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
    void write_sen(const std::string& name, const io::Sen& sen) const {
        std::ofstream out(file(name));
        io::write_sen(out, sen);
    }
};

}  // namespace

TEST_F(JobFiles, CalibrationRecoversAKnownGainAndBias) {
    // A 3-sample band; the cards' spectra differ per sample. The sensor we pretend to
    // be has gain 1234.5 and bias 17.25: the targets are what it would count.
    const double gain = 1234.5, bias = 17.25;
    image::Image cube(4, 6, 3);
    cube.wavelength_um = {0.5, 0.6, 0.8};  // Δλ = 0.1, 0.15, 0.2
    const float dark[3] = {0.01f, 0.02f, 0.015f}, bright[3] = {0.05f, 0.07f, 0.06f};
    for (int k = 0; k < 3; ++k)
        for (long r = 0; r < 4; ++r)
            for (long x = 0; x < 6; ++x) cube.at(k, r, x) = x < 3 ? dark[k] : bright[k];
    write_cube(file("cards.img"), cube, image::CubeFormat::Envi);
    // R = 1, 2, 1: L̄ = Σ R L Δ / Σ R Δ with Σ R Δ = 0.1 + 0.3 + 0.2 = 0.6.
    auto band_mean = [](const float* l) { return (0.1 * l[0] + 0.3 * l[1] + 0.2 * l[2]) / 0.6; };
    const double l_dark = band_mean(dark), l_bright = band_mean(bright);
    write_sen("b.sen", io::Sen{1, 0, {1, 2, 1}});
    SensorizeJob job;
    job.cube_path = file("cards.img");
    job.sen_paths = {file("b.sen")};
    job.output_path = file("out");
    job.calibrate = true;
    job.calibration = {
        {0, 0, 3, 2}, {1, 3, 2, 5}, {gain * l_dark + bias}, {gain * l_bright + bias}};
    const SensorizeReport report = run_sensorize(job);
    ASSERT_EQ(report.calibration.size(), 1u);
    // Radiances pass through float32: relative error ~1e-7, so gain within 1e-4
    // relative and bias within 1e-2 counts.
    EXPECT_NEAR(report.calibration[0].radiance1, l_dark, 1e-8);
    const io::Sen solved = io::read_sen_file(file("out/b.sen"));
    EXPECT_NEAR(solved.gain, gain, gain * 1e-4);
    EXPECT_NEAR(solved.bias, bias, 1e-2);
    EXPECT_EQ(solved.response, (std::vector<double>{1, 2, 1}));
}

TEST_F(JobFiles, FloatOutputIsTheBandRadiance) {
    image::Image cube(2, 2, 2);
    cube.data = {1, 2, 3, 4, 3, 4, 5, 6};
    cube.wavelength_um = {0.5, 0.6};
    write_cube(file("c.tif"), cube, image::CubeFormat::GeoTiff);
    write_sen("flat.sen", io::Sen{7, 3, {1, 1}});
    SensorizeJob job;
    job.cube_path = file("c.tif");
    job.sen_paths = {file("flat.sen")};
    job.output_path = file("r.tif");
    job.float_output = true;
    run_sensorize(job);
    const image::Image out = image::read_image(file("r.tif"));
    ASSERT_EQ(out.channels, 1);
    EXPECT_EQ(out.data, (std::vector<float>{2, 3, 4, 5}));  // flat response: the mean
}

TEST_F(JobFiles, CountsAreWrittenWithGainAndBias) {
    image::Image cube(1, 3, 1);
    cube.data = {0.0f, 0.5f, 2.0f};
    write_cube(file("c.img"), cube, image::CubeFormat::Envi);
    write_sen("s.sen", io::Sen{100, 10, {1}});
    SensorizeJob job;
    job.cube_path = file("c.img");
    job.sen_paths = {file("s.sen")};
    job.output_path = file("c.png");
    const SensorizeReport report = run_sensorize(job);
    EXPECT_EQ(image::read_image(file("c.png")).data, (std::vector<float>{10, 60, 210}));
    EXPECT_EQ(report.bands[0].clipped.high, 0u);
    job.bits = 8;
    job.output_path = std::string(1, '-');  // std::string("-") trips GCC 12 -Wrestrict
    EXPECT_THROW(run_sensorize(job), UsageError);
}
