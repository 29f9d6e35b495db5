// Parallel loops are injected: the VTK filter passes a vtkSMPTools-based
// implementation, the core's own tests run sequentially. Every parallel loop
// in the core writes only to its own index range (or adds integers into one
// atomic count, an order-free sum), so results do not depend on the number of
// threads.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

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

/// Progress in [0, 1]; returning true requests an abort. Called on the
/// calling thread only (VTK's UpdateProgress and its observers are not
/// thread-safe). A core function asked to abort stops early and returns a
/// partial result: the caller that asked discards it.
using ProgressCallback = std::function<bool(double)>;

/// `progress` restricted to [lo, hi] of the caller's range (null stays null).
inline ProgressCallback ProgressRange(const ProgressCallback& progress, double lo, double hi)
{
  if (!progress)
  {
    return nullptr;
  }
  return [progress, lo, hi](double f) { return progress(lo + (hi - lo) * f); };
}

/// parallelFor over [0, count) in consecutive chunks of at most `chunk`
/// items; after each chunk, `afterChunk(first, last)` runs on the calling
/// thread (to use the chunk's results, report progress) and stops the loop by
/// returning true. Returns false when stopped.
inline bool ForEachChunk(std::size_t count, std::size_t chunk, const ParallelFor& parallelFor,
  const std::function<void(std::size_t, std::size_t)>& body,
  const std::function<bool(std::size_t, std::size_t)>& afterChunk)
{
  for (std::size_t first = 0; first < count; first += chunk)
  {
    const std::size_t last = count - first < chunk ? count : first + chunk;
    parallelFor(last - first, [&](std::size_t begin, std::size_t end) { body(first + begin, first + end); });
    if (afterChunk(first, last))
    {
      return false;
    }
  }
  return true;
}

/// ForEachChunk with chunks sized by the time they take: the first holds
/// `chunk` items; a chunk that took less than `seconds` makes the next twice
/// as large (up to 8 times `chunk` items), one that took over four times as
/// long makes it half as large (down to `chunk` / 16). Each chunk ends in a
/// barrier - the threads wait for its slowest range - and in `afterChunk` on
/// the calling thread alone, so chunks of many cheap items cost that wait
/// many times (the turbine's subdivision at 1/64, 256-cell chunks: 2 % of
/// its time), while one fixed size large enough for them would keep an
/// abort waiting for seconds where each item takes milliseconds. A chunk
/// grows only after cheap ones, so an abort waits about `seconds` - unless
/// the items turn costly at once, then for at most 8 times what a chunk of
/// `chunk` of them takes. The sizes depend on the clock: use it only for
/// loops whose results do not depend on where the chunks end.
inline bool ForEachTimedChunk(std::size_t count, std::size_t chunk, double seconds, const ParallelFor& parallelFor,
  const std::function<void(std::size_t, std::size_t)>& body,
  const std::function<bool(std::size_t, std::size_t)>& afterChunk)
{
  using Clock = std::chrono::steady_clock;
  const std::size_t smallest = std::max<std::size_t>(1, chunk / 16), largest = 8 * chunk;
  std::size_t size = chunk;
  for (std::size_t first = 0; first < count;)
  {
    const std::size_t last = count - first < size ? count : first + size;
    const Clock::time_point start = Clock::now();
    parallelFor(last - first, [&](std::size_t begin, std::size_t end) { body(first + begin, first + end); });
    const double took = std::chrono::duration<double>(Clock::now() - start).count();
    if (afterChunk(first, last))
    {
      return false;
    }
    first = last;
    size = took < seconds ? std::min(largest, 2 * size) : took > 4.0 * seconds ? std::max(smallest, size / 2) : size;
  }
  return true;
}

/// ForEachChunk reporting the fraction done after each chunk: a long loop
/// stops within one chunk of an abort request instead of at its end (without
/// `progress`, one parallelFor). Returns false when aborted.
inline bool ChunkedFor(std::size_t count, std::size_t chunk, const ParallelFor& parallelFor,
  const std::function<void(std::size_t, std::size_t)>& body, const ProgressCallback& progress)
{
  if (!progress)
  {
    parallelFor(count, body);
    return true;
  }
  return ForEachChunk(count, chunk, parallelFor, body, [&](std::size_t, std::size_t last) {
    return progress(static_cast<double>(last) / static_cast<double>(count));
  });
}

/// Sorts `v` by `less`: 64 blocks sorted in parallel, then merged pairwise
/// in parallel rounds, reporting progress between them (a sequential sort of
/// millions of records takes seconds without an abort check). Returns false,
/// with `v` unsorted, when aborted.
template <typename T, typename Less>
bool ParallelSort(
  std::vector<T>& v, const Less& less, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  constexpr std::size_t Blocks = 64; // a power of two: the merge rounds pair them up exactly
  const std::size_t n = v.size();
  auto at = [&](std::size_t block) { return v.begin() + static_cast<std::ptrdiff_t>(n * block / Blocks); };
  if (!ChunkedFor(Blocks, 8, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b)
        {
          std::sort(at(b), at(b + 1), less);
        }
      }, ProgressRange(progress, 0.0, 0.6)))
  {
    return false;
  }
  double done = 0.6;
  for (std::size_t width = 1; width < Blocks; width *= 2)
  {
    parallelFor(Blocks / (2 * width), [&](std::size_t begin, std::size_t end) {
      for (std::size_t m = begin; m < end; ++m)
      {
        std::inplace_merge(at(2 * m * width), at((2 * m + 1) * width), at((2 * m + 2) * width), less);
      }
    });
    done += 0.4 / 6.0;
    if (progress && progress(done))
    {
      return false;
    }
  }
  return true;
}

} // namespace tpc
