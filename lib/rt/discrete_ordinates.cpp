// Placeholder until the solver lands (issue 3, in progress).
#include "rt/discrete_ordinates.hpp"

#include "core/error.hpp"

namespace sigchain::rt {
Result solve(const Problem&) { throw NotImplemented("discrete-ordinate solver: not written yet"); }
}  // namespace sigchain::rt
