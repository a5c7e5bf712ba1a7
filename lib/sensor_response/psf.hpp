// Point-spread functions: a normalised 2-D kernel applied to each band's radiance.
#pragma once

#include <string>
#include <vector>

namespace sigchain::sensor_response {

// An odd-sized kernel, weights summing to 1, centre at (rows / 2, columns / 2).
struct Kernel {
    int rows = 1;
    int columns = 1;
    std::vector<double> weights{1.0};  // row-major
};

// A sampled Gaussian exp(-(x² + y²) / (2σ²)) [σ in pixels], radius ceil(3σ), normalised
// to sum 1. σ must be positive.
Kernel gaussian_kernel(double sigma_px);

// Reads a kernel file (sensorize(1) PSF FILE): `#` comments and blank lines ignored;
// the first line "ROWS COLUMNS" (odd, 1..99), then ROWS lines of COLUMNS non-negative
// weights; the weights are normalised to sum 1 (their sum must be positive).
// "-" reads standard input. Throws DataError "FILE:LINE: ..." or IoError.
Kernel read_kernel_file(const std::string& path);

// Convolves one plane (rows x columns, row-major) with the kernel; pixels beyond the
// border take the value of the nearest edge pixel (clamp-to-edge), so a constant image
// stays constant and, away from the border, the plane's sum is preserved.
std::vector<float> convolve(const std::vector<float>& plane, long rows, long columns,
                            const Kernel& kernel);

}  // namespace sigchain::sensor_response
