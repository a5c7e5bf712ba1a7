// The image loop of a build without MPI: one process, render() over every row.
#include "trace/distributed.hpp"

namespace sigchain::trace {

bool render_rows(const RenderInputs& inputs, const RenderOptions& options,
                 const Reporter& reporter, RenderResult& result) {
    ProgressScope bar(reporter, "rendering");
    result = render(inputs, options, bar.callback());
    return true;
}

bool distributed_worker() { return false; }

}  // namespace sigchain::trace
