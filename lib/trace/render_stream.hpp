// The image loop with its rows handed on in order as they complete (render.cpp), so
// that a render holds a ring of rows, not its image (trace(1), OUTPUT).
#pragma once

#include <functional>

#include "image/image.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {

// Rows of a render handed on: rows [first, first + count) of the render (0 is
// options.row_begin) are rows [slot, slot + count) of `radiance` and of `truth` (no
// channels unless options.truth), the ring. The receiver may change them (their unit)
// before it writes them; they are overwritten once it returns.
struct RenderedRows {
    image::Image& radiance;
    image::Image& truth;
    long first = 0, slot = 0, count = 0;
};
using RowSink = std::function<void(const RenderedRows&)>;

// render(), with each row written into a ring of `ring_rows` rows (clamped to [1, rows];
// 0: every row, the whole image) and handed to `sink` (may be empty) in row order as
// soon as it and every row before it are complete. `sink` runs on one worker at a time
// while the others render the next rows; its exceptions end the render and are
// rethrown. The rows and their bytes are those of render(): rows are started in
// order, each computed from its own seeds. The result holds the statistics and the
// ring (the whole image when ring_rows is 0); its radiance.rows is the ring's.
RenderResult render_streamed(const RenderInputs& inputs, const RenderOptions& options,
                             long ring_rows, const RowSink& sink,
                             const std::function<void(long, long)>& progress = {});

}  // namespace sigchain::trace
