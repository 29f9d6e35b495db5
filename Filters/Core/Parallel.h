// Parallel loops are injected: the VTK filter passes a vtkSMPTools-based
// implementation, the core's own tests run sequentially. Every parallel loop
// in the core writes only to its own index range, so results do not depend on
// the number of threads.
#pragma once

#include <cstddef>
#include <functional>

namespace tpc
{

/// Calls body(begin, end) over disjoint ranges covering [0, count).
using ParallelFor =
  std::function<void(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)>;

inline void SequentialFor(
  std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  if (count > 0)
  {
    body(0, count);
  }
}

/// Progress in [0, 1]; returning true requests an abort.
using ProgressCallback = std::function<bool(double)>;

} // namespace tpc
