// Gaussian and tabulated point-spread functions, clamp-to-edge convolution.
#include "sensor_response/psf.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::sensor_response {

namespace {

void normalise(Kernel& k, const SourceLocation& where) {
    double sum = 0;
    for (double w : k.weights) sum += w;
    if (!(sum > 0)) throw DataError(where, "the kernel weights sum to zero");
    for (double& w : k.weights) w /= sum;
}

}  // namespace

Kernel gaussian_kernel(double sigma_px) {
    if (!(sigma_px > 0)) throw UsageError("--psf-sigma must be positive");
    const int radius = static_cast<int>(std::ceil(3 * sigma_px));
    Kernel k{2 * radius + 1, 2 * radius + 1, {}};
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x)
            k.weights.push_back(std::exp(-(x * x + y * y) / (2 * sigma_px * sigma_px)));
    normalise(k, {});
    return k;
}

Kernel read_kernel_file(const std::string& path) {
    const TextInput in = TextInput::from_file(path);
    LineCursor cursor(in);
    cursor.require_not_empty("'ROWS COLUMNS'");
    auto fields = cursor.fields(2, "'ROWS COLUMNS'");
    const SourceLocation size_line = cursor.where();
    Kernel k;
    k.rows = static_cast<int>(parse_long(fields[0], size_line, "ROWS"));
    k.columns = static_cast<int>(parse_long(fields[1], size_line, "COLUMNS"));
    for (int n : {k.rows, k.columns})
        if (n < 1 || n > 99 || n % 2 == 0)
            throw DataError(size_line,
                            "kernel sizes must be odd, 1 to 99, found " + std::to_string(n));
    k.weights.clear();
    for (int r = 0; r < k.rows; ++r) {
        fields = cursor.fields(static_cast<std::size_t>(k.columns), "a row of kernel weights");
        for (auto f : fields) {
            const double w = parse_double(f, cursor.where(), "weight");
            if (w < 0) throw DataError(cursor.where(), "weights must not be negative");
            k.weights.push_back(w);
        }
    }
    cursor.require_end("the kernel rows");
    normalise(k, size_line);
    return k;
}

std::vector<float> convolve(const std::vector<float>& plane, long rows, long columns,
                            const Kernel& kernel) {
    std::vector<float> out(plane.size());
    const int hr = kernel.rows / 2, hc = kernel.columns / 2;
    for (long r = 0; r < rows; ++r)
        for (long c = 0; c < columns; ++c) {
            double sum = 0;
            for (int i = 0; i < kernel.rows; ++i) {
                const long rr = std::clamp(r + i - hr, 0L, rows - 1);
                for (int j = 0; j < kernel.columns; ++j) {
                    const long cc = std::clamp(c + j - hc, 0L, columns - 1);
                    // Convolution: the kernel is mirrored (it need not be symmetric).
                    sum += kernel.weights[(kernel.rows - 1 - i) * kernel.columns +
                                          (kernel.columns - 1 - j)] *
                           plane[rr * columns + cc];
                }
            }
            out[r * columns + c] = static_cast<float>(sum);
        }
    return out;
}

}  // namespace sigchain::sensor_response
