// Facet temperatures for trace: the .tmp read and its keys checked against the scene's
// facets (trace(1), TEMPERATURES).
#pragma once

#include "core/report.hpp"
#include "radiometry/spectral.hpp"
#include "trace/trace_job.hpp"

namespace sigchain::trace {

// Facet temperatures by key from job.tmp_path (K); none without one, then a warning
// when the grid reaches wavelengths where emission matters. Keys that meet no facet,
// or facets without a key, are a warning, and with --strict a DataError.
Temperatures read_temperatures(const TraceJob& job, const radiometry::SpectralGrid& grid,
                               const scene::Scene& scene, const Reporter& reporter);

}  // namespace sigchain::trace
