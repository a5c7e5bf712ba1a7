// sensorize --uncertainty-cube: a per-band standard uncertainty of the counts from trace's
// radiance uncertainty layers (trace(1) UNCERTAINTY) and the noise model (noise.hpp).
#pragma once

#include <string>
#include <vector>

#include "image/image.hpp"
#include "sensor_response/noise.hpp"

namespace sigchain::sensor_response {

// The radiance uncertainty planes (W cm-2 sr-1 um-1, rows x columns each) of the truth
// cube at `truth_path`: its "uncertainty_*" layers in order, one per sensor band.
// Throws DataError naming the file when it has no such layers, a number other than
// `bands`, or another size than `cube`.
std::vector<std::vector<float>> read_radiance_uncertainty(const std::string& truth_path,
                                                          const image::Image& cube, int bands);

// In place: the radiance uncertainty sigma_L of one band's pixels becomes the counts
// uncertainty sqrt((gain sigma_L)^2 + noise variance) of the noise-free counts
// `counts` (gain L + bias): the input part through the gain and the noise model's
// per-pixel noise (noise_variance) in quadrature, as independent. Without a gain
// (float output, `counts` empty) sigma_L is left as it is.
void counts_uncertainty(std::vector<float>& sigma, const std::vector<float>& counts, double gain,
                        double bias, const NoiseModel& noise);

}  // namespace sigchain::sensor_response
