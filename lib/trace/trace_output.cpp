// trace's cubes as rows complete (trace_output.hpp).
#include "trace/trace_output.hpp"

#include <algorithm>
#include <cstdio>

#include "core/parallel.hpp"
#include "trace/black_cube.hpp"
#include "trace/radiance_units.hpp"

namespace sigchain::trace {

namespace {

// What the ring holds at most beyond its minimum of rows per worker.
constexpr double kRingBytes = 32.0 * 1024.0 * 1024.0;

// The radiance cube's header: one band per spectral sample, named "BAND λ um".
image::Image radiance_header(const radiometry::SpectralGrid& grid, const image::Georeference& georef,
                             const std::string& sensor_type, bool si, long rows, long columns) {
    image::Image h;
    h.rows = rows;
    h.columns = columns;
    h.channels = static_cast<int>(grid.size());
    h.georef = georef;
    h.sensor_type = sensor_type;
    h.wavelength_um = grid.wavelength_um;
    h.units = si ? kSiRadianceUnits : kRadianceUnits;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        char wavelength[32];
        std::snprintf(wavelength, sizeof wavelength, "%.6g", grid.wavelength_um[k]);
        h.channel_names.push_back(grid.band_names[grid.band_of_sample[k]] + " " + wavelength +
                                  " um");
    }
    return h;
}

// The truth cube's header: its layers by name, no wavelengths, no unit; the georeference
// without the arrays (written with the radiance cube).
image::Image truth_header(const radiometry::SpectralGrid& grid, const RenderOptions& options,
                          const image::Georeference& georef, const std::string& sensor_type,
                          long rows, long columns) {
    image::Image h;
    h.rows = rows;
    h.columns = columns;
    h.channel_names = truth_layer_names(grid, options);
    h.channels = static_cast<int>(h.channel_names.size());
    h.georef = georef;
    h.georef.arrays.reset();
    h.sensor_type = sensor_type;
    return h;
}

}  // namespace

long ring_rows(long rows, long columns, std::size_t floats_per_pixel, unsigned threads) {
    const double row_bytes = 4.0 * static_cast<double>(std::max(1L, columns)) *
                             static_cast<double>(std::max<std::size_t>(1, floats_per_pixel));
    const long workers = parallel_workers(rows, ParallelOptions{threads, {}});
    const long ring = std::max(4 * workers, static_cast<long>(kRingBytes / row_bytes));
    return std::clamp(ring, 1L, std::max(1L, rows));
}

TraceOutputs::TraceOutputs(const TraceJob& job, const image::WriteOptions& write_options,
                           const radiometry::SpectralGrid& grid, const RenderOptions& options,
                           const image::Georeference& georef, const std::string& sensor_type,
                           long rows, long columns)
    : m_si(job.si_radiance_units),
      m_radiance(job.output_path,
                 radiance_header(grid, georef, sensor_type, job.si_radiance_units, rows, columns),
                 image::cube_format_of(job.output_path), write_options) {
    if (job.truth_path.empty()) return;
    m_truth = std::make_unique<image::CubeStream>(
        job.truth_path, truth_header(grid, options, georef, sensor_type, rows, columns),
        image::cube_format_of(job.truth_path), write_options);
}

void TraceOutputs::write(const RenderedRows& rows) {
    if (m_si) rows_to_si_units(rows.radiance, rows.truth, rows.slot, rows.count);
    m_largest = largest_magnitude(rows.radiance, rows.slot, rows.count, m_largest);
    m_values += static_cast<std::size_t>(rows.count) *
                static_cast<std::size_t>(rows.radiance.columns) *
                static_cast<std::size_t>(rows.radiance.channels);
    m_radiance.append(rows.radiance, rows.slot, rows.count);
    if (m_truth) m_truth->append(rows.truth, rows.slot, rows.count);
}

void TraceOutputs::commit() {
    m_radiance.commit();
    if (m_truth) m_truth->commit();
}

void HeldReports::release() const {
    for (const auto& [kind, message] : m_held) {
        if (kind == 'w')
            m_later.warn(message);
        else if (kind == 'a')
            m_later.alarm(message);
        else if (kind == 'n')
            m_later.note(message);
        else
            m_later.info(message);
    }
    m_held.clear();
}

}  // namespace sigchain::trace
