// A pixel's running sample statistics at the band centres (render.cpp): the sampling
// truth layers (trace(1) --standard-error) and --convergence's stopping rule.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace sigchain::trace {

// Per-band running mean and sum of squared deviations (Welford, 1962) of a pixel's
// primary samples at the band-centre spectral sample: the sampling truth layers
// (trace(1) --standard-error) and --convergence's stopping rule.
struct SampleStats {
    long n = 0;
    std::vector<double> mean, m2;
    bool keep = false;           // keep the samples (--convergence's block estimate)
    std::vector<double> values;  // sample-major, per band: the block estimate's input
    void reset(std::size_t bands, bool keep_values) {
        n = 0;
        mean.assign(bands, 0.0);
        m2.assign(bands, 0.0);
        keep = keep_values;
        values.clear();
    }
    // Standard error from kBlocks consecutive blocks of the samples (each block of a
    // (0,2)-sequence is itself stratified): the spread of the block means, which
    // includes what stratification gains; sqrt(s^2 / n) below 2 kBlocks samples.
    static constexpr long kBlocks = 8;
    double block_error(std::size_t b) const {
        const long m = n / kBlocks;
        if (m < 2) return standard_error(b);
        const std::size_t bands = mean.size();
        double sum = 0, sum2 = 0;
        for (long k = 0; k < kBlocks; ++k) {
            double s = 0;
            for (long i = k * m; i < (k + 1) * m; ++i)
                s += values[static_cast<std::size_t>(i) * bands + b];
            s /= static_cast<double>(m);
            sum += s;
            sum2 += s * s;
        }
        const double kb = kBlocks, var = std::max(0.0, (sum2 - sum * sum / kb) / (kb - 1));
        return std::sqrt(var / kb);
    }
    void add(const std::vector<double>& sample, const std::vector<std::size_t>& centre) {
        ++n;
        if (keep)
            for (std::size_t b = 0; b < centre.size(); ++b) values.push_back(sample[centre[b]]);
        for (std::size_t b = 0; b < centre.size(); ++b) {
            const double x = sample[centre[b]], d = x - mean[b];
            mean[b] += d / static_cast<double>(n);
            m2[b] += d * (x - mean[b]);
        }
    }
    // Standard error of the mean, sqrt(s^2 / n) with s^2 = m2 / (n - 1); -1 below 2 samples.
    double standard_error(std::size_t b) const {
        if (n < 2) return -1;
        return std::sqrt(m2[b] / static_cast<double>(n - 1) / static_cast<double>(n));
    }
    // max over bands of standard error / unit(b), with the unit of each band from
    // `unit_of` (0 / 0 counts as 0, x / 0 as infinite; infinite below 2 samples): the
    // one loop of the three rules below.
    template <class Unit>
    double worst_error(Unit unit_of) const {
        double worst = 0;
        for (std::size_t b = 0; b < mean.size(); ++b) {
            const double se = block_error(b);
            if (se < 0) return std::numeric_limits<double>::infinity();
            if (se == 0) continue;
            const double unit = unit_of(b);
            worst = std::max(worst, unit == 0 ? std::numeric_limits<double>::infinity()
                                              : se / unit);
        }
        return worst;
    }
    // max over bands of standard error / |mean|.
    double relative_error() const {
        return worst_error([&](std::size_t b) { return std::abs(mean[b]); });
    }
    // max over bands of standard error / scale[b]; a band whose scale is not positive
    // counts as in relative_error.
    double scaled_error(const std::vector<double>& scale) const {
        return worst_error(
            [&](std::size_t b) { return scale[b] > 0 ? scale[b] : std::abs(mean[b]); });
    }
    // max over bands of the standard error.
    double absolute_error() const {
        return worst_error([](std::size_t) { return 1.0; });
    }
};

}  // namespace sigchain::trace
