// Rendering: primary rays from a sensor (sensor.hpp), the radiance at each hit from the
// hemisphere above it (by a sampling strategy), and the atmosphere's path terms;
// one geometry pass serves all spectral samples (White (1996), section 3.4, 3.6.5, 5.2;
// trace(1), RADIOMETRY).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "radiometry/atmosphere.hpp"
#include "trace/render_options.hpp"

namespace sigchain::trace {

// Names of the truth layers, in channel order (trace(1) TRUTH LAYERS). Reflectance
// is one layer per band ("reflectance_BAND").
std::vector<std::string> truth_layer_names(const radiometry::SpectralGrid& grid);
// The same, with the sampling layers when options.sampling_layers and the uncertainty
// layers when options.uncertainty_layers.
std::vector<std::string> truth_layer_names(const radiometry::SpectralGrid& grid,
                                           const RenderOptions& options);

struct RenderResult {
    image::Image radiance;  // rows = row_end - row_begin, one channel per grid sample
    image::Image truth;     // empty unless options.truth
    RenderStats stats;
};

// Renders rows [row_begin, row_end), spread over options.threads by
// sigchain::parallel_for: the image does not depend on the thread count.
// `progress(done rows, total rows)` is called now and then, never by two threads at
// once but from any of them, last with (total, total) (may be empty). Throws DataError for a hit
// facet whose material is missing (validate_scene() catches those first).
RenderResult render(const RenderInputs& inputs, const RenderOptions& options,
                    const std::function<void(long, long)>& progress = {});

// Every placed facet's material exists: else DataError naming the facet's origin.
void validate_scene(const scene::Scene& scene, const radiometry::MaterialLibrary& materials);

}  // namespace sigchain::trace
