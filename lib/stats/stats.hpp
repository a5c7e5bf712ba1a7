// Descriptive statistics and rank-order correlation for compare(1): ranks, Spearman's
// rho (White (1996), section 3.5), RMS difference, bias, mean, standard deviation, median and
// histograms with shared bin edges.
//
// All functions take plain value sequences and are pure (thread-safe). Bad arguments
// (too few values, NaN, sequences of different lengths) throw StatsError with a
// message that callers wrap with the file and band in question.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace sigchain::stats {

// A statistic the values leave undefined (too few values, NaN, all values tied,
// sequences of different lengths, a value outside a histogram's range). what() is the
// bare reason: the values carry no file or line, so a caller that knows them rethrows
// a DataError at the record concerned. Uncaught, it is still an Error (exit status 1
// with the message), not an internal error.
class StatsError : public Error {
public:
    using Error::Error;
};

// Ranks 1..n in ascending order of value (rank 1 = lowest, as in White (1996), tables 4.5 and
// 4.6); tied values all get the mean of the ranks they span ("average ranks").
std::vector<double> average_ranks(std::span<const double> values);

// Whether any two values are equal.
bool has_ties(std::span<const double> values);

enum class RankMethod {
    Spearman,     // no ties: rho = 1 - 6 sum d^2 / (n^3 - n)
    TieCorrected  // ties: Pearson correlation of the average ranks
};
const char* rank_method_name(RankMethod method);  // "spearman" or "tie-corrected"

struct RankCorrelation {
    double rho = 0;  // in [-1, 1]
    RankMethod method = RankMethod::Spearman;
};

// Rank-order correlation of two paired samples (n >= 2, no NaN). Without ties in
// either sample, Spearman's formula of White (1996), section 3.5; with ties, the Pearson correlation of
// the average ranks (the tie-corrected coefficient). Throws StatsError for
// n < 2 (undefined), NaN, different lengths, or a sample whose values all tie (its
// ranks have no spread, so the correlation is undefined).
RankCorrelation rank_order_correlation(std::span<const double> a, std::span<const double> b);

// Pearson's product-moment correlation (n >= 2; throws if either sample is constant).
double pearson(std::span<const double> a, std::span<const double> b);

// sqrt(mean((a - b)^2)): the RMS error of White (1996), section 3.5. Same length, n >= 1.
double rms_difference(std::span<const double> a, std::span<const double> b);
// mean(a - b): positive when `a` is brighter on average. Same length, n >= 1.
double bias(std::span<const double> a, std::span<const double> b);

double mean(std::span<const double> values);  // n >= 1
// Population standard deviation (divides by n): the whole image is the population
// described (White (1996), table 4.7), not a sample from a larger one. n >= 1.
double population_std(std::span<const double> values);
// The middle value; for an even count the mean of the two middle values. n >= 1.
double median(std::span<const double> values);

// Equal-width bins over [lo, hi]: bin i covers [lo + i w, lo + (i + 1) w), the last
// bin also holds hi. When lo == hi there is a single bin holding everything.
struct Histogram {
    double lo = 0;
    double hi = 0;
    std::vector<long> counts;
    double bin_width() const;
    double edge(std::size_t i) const;  // lower edge of bin i; edge(counts.size()) = hi
};

// The common range of several samples, so their histograms share edges: the smallest
// and largest values of all of them. Throws if they are all empty.
struct Range {
    double lo = 0;
    double hi = 0;
};
Range common_range(std::span<const std::span<const double>> samples);

// Counts `values` into `bins` equal bins over `range` (values outside are an error:
// use common_range). bins >= 1.
Histogram histogram(std::span<const double> values, Range range, int bins);

// Throws StatsError "WHAT: NaN at index I" for the first NaN.
void require_no_nan(std::span<const double> values, const std::string& what);

}  // namespace sigchain::stats
