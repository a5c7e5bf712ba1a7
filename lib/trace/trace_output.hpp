// trace's cubes written as the render's rows complete (trace(1), OUTPUT): the radiance
// cube and the truth cube, each an image::CubeStream, so that trace holds its scene and
// a ring of rows, not the cubes.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/report.hpp"
#include "image/cube_stream.hpp"
#include "radiometry/spectral.hpp"
#include "trace/render_stream.hpp"
#include "trace/trace_job.hpp"

namespace sigchain::trace {

// The ring of rows a render of `rows` x `columns` pixels of `floats_per_pixel` values
// (cube and truth channels) holds with `threads` (0: all cores): about 32 MiB, and at
// least 4 rows per worker so that the workers seldom wait for the row before theirs;
// at most the image.
long ring_rows(long rows, long columns, std::size_t floats_per_pixel, unsigned threads);

class TraceOutputs {
public:
    // Starts the radiance cube at job.output_path and, with job.truth_path, the truth
    // cube (its layers those of `options`), of `rows` x `columns` pixels, their headers
    // as cube(5) gives them: `grid`'s wavelengths and band names, `georef` (the
    // geolocation arrays go with the radiance cube), `sensor_type`, the unit of
    // --radiance-units. Throws what image::CubeStream throws.
    TraceOutputs(const TraceJob& job, const image::WriteOptions& write_options,
                 const radiometry::SpectralGrid& grid, const RenderOptions& options,
                 const image::Georeference& georef, const std::string& sensor_type, long rows,
                 long columns);
    // The sink of the render (render_stream.hpp): the rows in W m-2 sr-1 um-1 when asked
    // (changed in the ring), appended to the cubes.
    void write(const RenderedRows& rows);
    // Commits the radiance cube, then the truth cube, each atomically (as one output
    // with its geolocation arrays).
    void commit();
    // The largest magnitude among the radiance cube's values, and their number
    // (alarm_if_black).
    float largest_radiance() const { return m_largest; }
    std::size_t values() const { return m_values; }

private:
    bool m_si = false;
    image::CubeStream m_radiance;
    std::unique_ptr<image::CubeStream> m_truth;
    float m_largest = 0;
    std::size_t m_values = 0;
};

// Reports kept to be told later, in their order (trace's georeferencing is made before
// the render, for the cubes' headers, and told after it, where -v has always told it).
class HeldReports : public Reporter {
public:
    explicit HeldReports(const Reporter& later) : m_later(later) {}
    void warn(const std::string& message) const override { m_held.push_back({'w', message}); }
    void alarm(const std::string& message) const override { m_held.push_back({'a', message}); }
    void note(const std::string& message) const override { m_held.push_back({'n', message}); }
    void info(const std::string& message) const override { m_held.push_back({'i', message}); }
    bool verbose() const override { return m_later.verbose(); }
    // Tells the held reports to the reporter given at construction, and forgets them.
    void release() const;

private:
    const Reporter& m_later;
    mutable std::vector<std::pair<char, std::string>> m_held;
};

}  // namespace sigchain::trace
