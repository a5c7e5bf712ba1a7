// Descriptive statistics and rank-order correlation (see stats.hpp).
#include "stats/stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sigchain::stats {

namespace {

void require_same_size(std::span<const double> a, std::span<const double> b) {
    if (a.size() != b.size())
        throw StatsError("samples of different lengths (" + std::to_string(a.size()) + " and " +
                         std::to_string(b.size()) + ")");
}

void require_some(std::span<const double> values) {
    if (values.empty()) throw StatsError("no values");
}

}  // namespace

std::vector<double> average_ranks(std::span<const double> values) {
    require_no_nan(values, "ranks");
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t i, std::size_t j) { return values[i] < values[j]; });
    std::vector<double> ranks(values.size());
    for (std::size_t first = 0; first < order.size();) {
        std::size_t last = first;  // the run [first, last] of equal values
        while (last + 1 < order.size() && values[order[last + 1]] == values[order[first]]) ++last;
        // Ranks first+1 .. last+1 averaged: their mean is the midpoint.
        double rank = (static_cast<double>(first) + static_cast<double>(last)) / 2.0 + 1.0;
        for (std::size_t k = first; k <= last; ++k) ranks[order[k]] = rank;
        first = last + 1;
    }
    return ranks;
}

bool has_ties(std::span<const double> values) {
    std::vector<double> sorted(values.begin(), values.end());
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

const char* rank_method_name(RankMethod method) {
    return method == RankMethod::Spearman ? "spearman" : "tie-corrected";
}

double pearson(std::span<const double> a, std::span<const double> b) {
    require_same_size(a, b);
    if (a.size() < 2) throw StatsError("fewer than 2 values: correlation undefined");
    double ma = mean(a), mb = mean(b);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    if (saa == 0 || sbb == 0) throw StatsError("all values are equal: correlation undefined");
    // r = sum (a - ma)(b - mb) / sqrt(sum (a - ma)^2 sum (b - mb)^2) (Pearson 1896).
    return sab / std::sqrt(saa * sbb);
}

RankCorrelation rank_order_correlation(std::span<const double> a, std::span<const double> b) {
    require_same_size(a, b);
    if (a.size() < 2)
        throw StatsError("fewer than 2 points: the rank-order correlation is undefined");
    require_no_nan(a, "first sample");
    require_no_nan(b, "second sample");
    auto ra = average_ranks(a);
    auto rb = average_ranks(b);
    if (has_ties(a) || has_ties(b)) {
        // Ties: Spearman's coefficient generalised as the Pearson correlation of the
        // average ranks (Kendall & Gibbons, Rank Correlation Methods, ch. 3).
        return {pearson(ra, rb), RankMethod::TieCorrected};
    }
    double sum_d2 = 0;
    for (std::size_t i = 0; i < ra.size(); ++i) sum_d2 += (ra[i] - rb[i]) * (ra[i] - rb[i]);
    double n = static_cast<double>(a.size());
    // rho = 1 - 6 sum d^2 / (n^3 - n) (White (1996), section 3.5, Servoss 1993).
    return {1.0 - 6.0 * sum_d2 / (n * n * n - n), RankMethod::Spearman};
}

double rms_difference(std::span<const double> a, std::span<const double> b) {
    require_same_size(a, b);
    require_some(a);
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
    // RMS = sqrt(sum (a - b)^2 / n) (White (1996), section 3.5).
    return std::sqrt(sum / static_cast<double>(a.size()));
}

double bias(std::span<const double> a, std::span<const double> b) {
    require_same_size(a, b);
    require_some(a);
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] - b[i];
    return sum / static_cast<double>(a.size());
}

double mean(std::span<const double> values) {
    require_some(values);
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double population_std(std::span<const double> values) {
    double m = mean(values);
    double sum = 0;
    for (double v : values) sum += (v - m) * (v - m);
    // sigma = sqrt(sum (x - mean)^2 / n): the population form.
    return std::sqrt(sum / static_cast<double>(values.size()));
}

double median(std::span<const double> values) {
    require_some(values);
    std::vector<double> v(values.begin(), values.end());
    std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(mid), v.end());
    double upper = v[mid];
    if (v.size() % 2 == 1) return upper;
    double lower = *std::max_element(v.begin(), v.begin() + static_cast<long>(mid));
    return (lower + upper) / 2.0;
}

double Histogram::bin_width() const {
    return counts.empty() ? 0.0 : (hi - lo) / static_cast<double>(counts.size());
}

double Histogram::edge(std::size_t i) const {
    return i >= counts.size() ? hi : lo + static_cast<double>(i) * bin_width();
}

Range common_range(std::span<const std::span<const double>> samples) {
    bool any = false;
    Range r;
    for (auto s : samples)
        for (double v : s) {
            if (!any) r = {v, v};
            any = true;
            r.lo = std::min(r.lo, v);
            r.hi = std::max(r.hi, v);
        }
    if (!any) throw StatsError("no values for a histogram");
    return r;
}

Histogram histogram(std::span<const double> values, Range range, int bins) {
    if (bins < 1) throw StatsError("a histogram needs at least 1 bin");
    Histogram h{range.lo, range.hi, {}};
    h.counts.assign(range.hi > range.lo ? static_cast<std::size_t>(bins) : 1, 0);
    double width = h.bin_width();
    for (double v : values) {
        if (!(v >= range.lo && v <= range.hi))
            throw StatsError("value outside the histogram range");
        std::size_t i = width > 0 ? static_cast<std::size_t>((v - range.lo) / width) : 0;
        h.counts[std::min(i, h.counts.size() - 1)] += 1;
    }
    return h;
}

void require_no_nan(std::span<const double> values, const std::string& what) {
    for (std::size_t i = 0; i < values.size(); ++i)
        if (std::isnan(values[i])) throw StatsError(what + ": NaN at index " + std::to_string(i));
}

}  // namespace sigchain::stats
