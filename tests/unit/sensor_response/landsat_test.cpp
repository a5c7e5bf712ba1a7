// Tests for a Landsat band as sigchain's sensor (lib/sensor_response/landsat): the ETM+ gain states,
// and the band radiance sensorize forms from the .sen responses against independent integrals.
#include "sensor_response/landsat.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "image/image.hpp"
#include "io/rsr.hpp"
#include "sensor_response/band.hpp"

using namespace sigchain;
using namespace sigchain::sensor_response;

namespace {

const std::string kMarburg = SIGCHAIN_SOURCE_DIR "/data/scenes/marburg/";
const std::string kEtm = kMarburg + "LE07_L1TP_195025_20010730_20170204_01_T1_MTL.txt";
const std::string kOli = kMarburg + "LC08_L1TP_195025_20130707_20170503_01_T1_MTL.txt";
const std::string kSpectra = SIGCHAIN_SOURCE_DIR "/data/spectra/";

struct Warnings final : Reporter {
    mutable std::vector<std::string> seen;
    void warn(const std::string& m) const override { seen.push_back(m); }
};

io::Mtl hand_written(const std::string& bands) {
    return io::parse_mtl(TextInput::from_string(
        "GROUP = L1_METADATA_FILE\n"
        "  SPACECRAFT_ID = \"LANDSAT_7\"\n  SENSOR_ID = \"ETM\"\n"
        "  DATE_ACQUIRED = 2001-07-30\n  SCENE_CENTER_TIME = \"10:04:52Z\"\n"
        "  CORNER_UL_LAT_PRODUCT = 51\n  CORNER_UL_LON_PRODUCT = 7\n"
        "  CORNER_UR_LAT_PRODUCT = 51\n  CORNER_UR_LON_PRODUCT = 10\n"
        "  CORNER_LL_LAT_PRODUCT = 49\n  CORNER_LL_LON_PRODUCT = 7\n"
        "  CORNER_LR_LAT_PRODUCT = 49\n  CORNER_LR_LON_PRODUCT = 10\n"
        "  SUN_AZIMUTH = 144\n  SUN_ELEVATION = 54\n" +
            bands + "END_GROUP = L1_METADATA_FILE\nEND\n",
        "hand.mtl"));
}

// Band radiance of `spectrum(lambda_um)` as sensorize forms it from a band's .sen responses:
// through sensor_response::band_radiance on a one-pixel cube with the .rad's wavelengths.
double sensorize_radiance(const BandSpectrum& s, double (*spectrum)(double)) {
    const long n = s.band.sample_count();
    image::Image cube(1, 1, static_cast<int>(n));
    for (long k = 0; k < n; ++k) {
        cube.wavelength_um.push_back(1e4 / (s.band.max_wavenumber_cm1 - k * s.band.increment_cm1));
        cube.at(static_cast<int>(k), 0, 0) = static_cast<float>(spectrum(cube.wavelength_um.back()));
    }
    const auto widths = sample_widths_um(cube.wavelength_um, static_cast<int>(n));
    return band_radiance(cube, {0, static_cast<int>(n)}, s.response, widths, "t.sen")[0];
}

// Planck's spectral radiance at 5800 K (shape only: W m-2 sr-1 um-1 up to a constant).
double planck_5800(double um) {
    const double c2 = 14387.77;  // um K
    return 1e4 / (std::pow(um, 5) * (std::exp(c2 / (um * 5800)) - 1));
}
double ramp(double um) { return 1 + 2 * um; }

}  // namespace

TEST(LandsatGain, MarburgBand4IsLowGainAndMatchesTheTable) {
    io::Mtl m = io::read_mtl_file(kEtm);
    Warnings w;
    auto c = band_calibration(m, "4", {}, kEtm, w);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->gain_state, 'L');
    EXPECT_EQ(c->source, "MTL");
    const auto table = etm_table_rescaling(*etm_gain_range("4", 'L'));
    EXPECT_NEAR(c->rescaling.mult, table.mult, 1e-5);  // 9.6929E-01 = (241.1 + 5.1) / 254
    EXPECT_NEAR(c->rescaling.add, table.add, 1e-5);
    for (const auto& b : m.bands) band_calibration(m, b.name, {}, kEtm, w);
    EXPECT_TRUE(w.seen.empty()) << w.seen.front();
}

TEST(LandsatGain, AFileWithOnlyTheGainStateTakesTheTable) {
    io::Mtl m = hand_written("  GAIN_BAND_4 = \"L\"\n  GAIN_BAND_3 = \"H\"\n");
    Warnings w;
    auto c4 = band_calibration(m, "4", {}, "hand.mtl", w);
    ASSERT_TRUE(c4);
    EXPECT_EQ(c4->source, "table (low gain)");
    EXPECT_DOUBLE_EQ(c4->rescaling.mult, (241.1 + 5.1) / 254);
    EXPECT_DOUBLE_EQ(c4->rescaling.add, -5.1 - (241.1 + 5.1) / 254);
    EXPECT_DOUBLE_EQ(band_calibration(m, "3", {}, "hand.mtl", w)->rescaling.mult, (152.9 + 5.0) / 254);
    EXPECT_FALSE(band_calibration(m, "2", {}, "hand.mtl", w));  // no gain, no rescaling
}

TEST(LandsatGain, OverrideChoosesTheTableOfTheOtherGain) {
    io::Mtl m = io::read_mtl_file(kEtm);
    Warnings w;
    auto c = band_calibration(m, "4", parse_gain_overrides("4=H,1=L"), kEtm, w);
    EXPECT_EQ(c->gain_state, 'H');
    EXPECT_EQ(c->source, "table (high gain, --gain)");
    EXPECT_DOUBLE_EQ(c->rescaling.mult, (157.4 + 5.1) / 254);
    EXPECT_THROW(parse_gain_overrides("4=X"), UsageError);
    EXPECT_THROW(parse_gain_overrides("9=H"), UsageError);
    EXPECT_THROW(parse_gain_overrides("4=H,"), UsageError);
    io::Mtl oli = io::read_mtl_file(kOli);
    EXPECT_THROW(band_calibration(oli, "4", parse_gain_overrides("4=H"), kOli, w), UsageError);
}

TEST(LandsatGain, RescalingThatContradictsTheGainStateWarns) {
    // The low-gain rescaling of band 4 with a stated high gain.
    io::Mtl m = hand_written("  GAIN_BAND_4 = \"H\"\n  RADIANCE_MULT_BAND_4 = 9.6929E-01\n"
                             "  RADIANCE_ADD_BAND_4 = -6.06929\n");
    Warnings w;
    auto c = band_calibration(m, "4", {}, "hand.mtl", w);
    EXPECT_DOUBLE_EQ(c->rescaling.mult, 9.6929E-01);  // the file's is used
    ASSERT_EQ(w.seen.size(), 1u);
    EXPECT_EQ(w.seen[0], "hand.mtl:17: band 4: radiance rescaling 0.96929 per DN is not the "
                         "high-gain value 0.639763779527559 of Chander et al. (2009) but the "
                         "low-gain one (the file's gain state on line 16); the file's rescaling "
                         "is used (--gain 4=H|L to choose)");
}

TEST(LandsatGain, SenGainAndBiasReproduceTheMtlRescaling) {
    // DN = gain * L_cube + bias with L_cube in W cm-2 sr-1 um-1 = 1e-4 L(W m-2 sr-1 um-1).
    io::Mtl m = io::read_mtl_file(kEtm);
    Warnings w;
    for (const char* band : {"1", "4", "7"}) {
        auto c = band_calibration(m, band, {}, kEtm, w);
        for (double dn : {1.0, 37.0, 128.0, 255.0}) {
            const double l = c->rescaling.mult * dn + c->rescaling.add;
            EXPECT_NEAR(sen_gain(c->rescaling) * (l * 1e-4) + sen_bias(c->rescaling), dn, 1e-9) << band;
        }
    }
}

TEST(LandsatSpectrum, ResponseAreaIsTheExactPiecewiseLinearIntegral) {
    const std::vector<double> wl{500, 510, 520}, r{0, 1, -0.5};  // negative taken as 0
    EXPECT_DOUBLE_EQ(response_area_nm(wl, r, 0, 1000), 5 + 5);
    EXPECT_DOUBLE_EQ(response_area_nm(wl, r, 505, 510), (0.5 + 1) / 2 * 5);
    EXPECT_DOUBLE_EQ(response_area_nm(wl, r, 490, 500), 0);
}

TEST(LandsatSpectrum, FlatSpectrumGivesTheFlatValueForAnyResponse) {
    const io::RsrTable etm = io::read_rsr_file(kSpectra + "landsat7_etm_rsr.txt");
    for (std::size_t b = 0; b < etm.band_names.size(); ++b)
        for (int samples : {2, 5, 12, 40}) {
            SpectralOptions o;
            o.samples = samples;
            const BandSpectrum s = band_spectrum(etm.wavelength_nm, etm.response[b], o);
            ASSERT_EQ(s.band.sample_count(), samples);
            ASSERT_EQ(static_cast<int>(s.response.size()), samples);
            // sum(R w L) / sum(R w) = L: the float cube's value back within float rounding.
            EXPECT_FLOAT_EQ(sensorize_radiance(s, [](double) { return 0.0123; }), 0.0123f)
                << etm.band_names[b] << " " << samples;
        }
}

// Band radiance of the Landsat definition, integral RSR(l) L(l) dl / integral RSR(l) dl, by the
// trapezoid rule on the RSR's own 1 nm grid, against sensorize's from the .sen responses. The
// responses carry each sample's exact RSR area, so the only error is L's variation across a
// sample: |error| <= max |d ln L / d lambda| x (widest sample interval) / 2, plus the share of
// the RSR's area outside the band's span (taken as a full relative deviation of 2).
TEST(LandsatSpectrum, NonFlatSpectraMatchAnIndependentIntegration) {
    for (const char* file : {"landsat7_etm_rsr.txt", "landsat8_oli_rsr.txt"}) {
        const io::RsrTable t = io::read_rsr_file(kSpectra + file);
        for (std::size_t b = 0; b < t.band_names.size(); ++b)
            for (auto spectrum : {planck_5800, ramp}) {
                const auto& wl = t.wavelength_nm;
                const auto& r = t.response[b];
                double num = 0, den = 0, slope = 0;
                for (std::size_t i = 0; i + 1 < wl.size(); ++i) {
                    const double r0 = std::max(r[i], 0.0), r1 = std::max(r[i + 1], 0.0);
                    const double l0 = spectrum(wl[i] / 1000), l1 = spectrum(wl[i + 1] / 1000);
                    num += (r0 * l0 + r1 * l1) / 2 * (wl[i + 1] - wl[i]);
                    den += (r0 + r1) / 2 * (wl[i + 1] - wl[i]);
                    if (r0 > 0 || r1 > 0)
                        slope = std::max(slope, std::abs(std::log(l1 / l0)) / (wl[i + 1] - wl[i]));
                }
                const double reference = num / den;
                const BandSpectrum s = band_spectrum(wl, r, SpectralOptions{});
                const double nu = s.band.min_wavenumber_cm1, inc = s.band.increment_cm1;
                const double widest_nm = 1e7 / (nu - inc / 2) - 1e7 / (nu + inc / 2);
                const double tolerance = slope * widest_nm / 2 + 2 * (1 - s.captured_fraction) + 1e-6;
                const double got = sensorize_radiance(s, spectrum);
                EXPECT_NEAR(got / reference - 1, 0, tolerance) << file << " " << t.band_names[b];
            }
    }
}

TEST(LandsatSpectrum, IncrementOptionRoundsTheSpanOutToTheStep) {
    const io::RsrTable etm = io::read_rsr_file(kSpectra + "landsat7_etm_rsr.txt");
    SpectralOptions o;
    o.increment_cm1 = 5;
    const BandSpectrum s = band_spectrum(etm.wavelength_nm, etm.response[0], o);
    EXPECT_EQ(std::fmod(s.band.min_wavenumber_cm1, 5), 0);
    EXPECT_EQ(std::fmod(s.band.max_wavenumber_cm1, 5), 0);
    EXPECT_LE(s.band.min_wavenumber_cm1, 1e7 / s.threshold_hi_nm);
    EXPECT_GE(s.band.max_wavenumber_cm1, 1e7 / s.threshold_lo_nm);
    EXPECT_GT(s.captured_fraction, 0.9999);
}
