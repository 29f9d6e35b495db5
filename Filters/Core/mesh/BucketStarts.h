// Counting sorts (the edge table, the triangles around each vertex, the
// self-intersection check's bins, the inside test's ray grid): each bucket's count goes to start[k + 1],
// the counts are summed (std::partial_sum: start[k] is then bucket k's first
// slot, start.back() the end), and bucket k is filled from start[k] upwards,
// which leaves each start at the next bucket's. RestoreBucketStarts moves
// them back up one place. (Filling from a copy of the starts first touched
// as many pages again - up to 8 bins a triangle in the check's grid - each
// a fault of about 11 us on the benchmark machine.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tpc
{

/// The starts of a counting sort's buckets, after their fill (above), as
/// they were before it. `start` has one entry more than there are buckets.
template <typename Index>
void RestoreBucketStarts(std::vector<Index>& start)
{
  std::copy_backward(start.begin(), start.end() - 1, start.end());
  start[0] = 0;
}

} // namespace tpc
