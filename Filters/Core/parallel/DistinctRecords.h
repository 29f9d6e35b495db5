// Distinct records gathered in parallel: the unseen corners of a subdivision
// level (each sign evaluated once) and the crossing vertices of the
// extraction (each vertex placed once) are both many records with repeats.
//
// Blocks of work emit records in parallel, each into the bucket of its key's
// hash (each block's part of a bucket deduplicated at once); each bucket is
// then sorted and deduplicated on its own in the output, in parallel and in
// chunks reporting progress (one global sort of tens of millions of records
// takes seconds without an abort check). The result is the buckets
// concatenated, with where each starts, so a record is found by a binary
// search in its bucket. Which record of a repeated key is kept depends only
// on `less`, never on the number of threads.
#pragma once

#include "Parallel.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tpc
{

template <typename Record>
struct BucketedRecords
{
  std::vector<Record> Records;          ///< the buckets' distinct records, bucket after bucket
  std::vector<std::size_t> BucketStart; ///< where bucket k starts in Records (one more: the end)
};

/// Calls emit(b, out) for each block b < `blocks` (in parallel), which hands
/// its records to out(record); each lands in bucket bucketOf(record) <
/// `buckets`. Each bucket is sorted by `less`, and of each run of records
/// that `sameKey` calls equal the first is kept. Progress: emitting (and
/// each block's parts sorted) over the first half, the buckets over the
/// second; false when it asked to stop (`out` is then unusable).
template <typename Record, typename Emit, typename BucketOf, typename Less, typename SameKey>
bool GatherDistinct(std::size_t blocks, std::size_t buckets, const Emit& emit, const BucketOf& bucketOf,
  const Less& less, const SameKey& sameKey, const ParallelFor& parallelFor, const ProgressCallback& progress,
  BucketedRecords<Record>& out)
{
  // Pass 1: each block's records, by bucket, each part sorted and
  // deduplicated on its own. (Most repeats come from one block - a corner or
  // a crossing shared by neighbouring cells, which are mostly one block's -
  // so the output below is filled about once, not once per repeat. The
  // first of a key's repeats by `less` in each part, then the first of
  // those: the first of them all.)
  std::vector<std::vector<Record>> parts(blocks * buckets);
  if (!ChunkedFor(blocks, 8, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b)
        {
          emit(b, [&parts, &bucketOf, b, buckets](const Record& r) { parts[b * buckets + bucketOf(r)].push_back(r); });
          for (std::size_t k = 0; k < buckets; ++k)
          {
            std::vector<Record>& part = parts[b * buckets + k];
            std::sort(part.begin(), part.end(), less);
            part.erase(std::unique(part.begin(), part.end(), sameKey), part.end());
          }
        }
      }, ProgressRange(progress, 0.0, 0.5)))
  {
    return false;
  }
  // Pass 2: each bucket gathered from the blocks (in block order) where its
  // records start in the output, sorted and deduplicated there. (Gathered
  // into a bucket of its own and then copied, the records filled twice the
  // pages - a fifth of the extraction's vertex step, at about 11 us a page
  // first touched on the benchmark machine.)
  std::vector<std::size_t> start(buckets + 1, 0);
  for (std::size_t k = 0; k < buckets; ++k)
  {
    start[k + 1] = start[k];
    for (std::size_t b = 0; b < blocks; ++b)
    {
      start[k + 1] += parts[b * buckets + k].size();
    }
  }
  out.Records.resize(start[buckets]);
  std::vector<std::size_t> kept(buckets);
  if (!ChunkedFor(buckets, 8, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k)
        {
          const auto first = out.Records.begin() + static_cast<std::ptrdiff_t>(start[k]);
          auto last = first;
          for (std::size_t b = 0; b < blocks; ++b)
          {
            last = std::copy(parts[b * buckets + k].begin(), parts[b * buckets + k].end(), last);
            std::vector<Record>().swap(parts[b * buckets + k]);
          }
          std::sort(first, last, less);
          kept[k] = static_cast<std::size_t>(std::unique(first, last, sameKey) - first);
        }
      }, ProgressRange(progress, 0.5, 1.0)))
  {
    return false;
  }
  // Pass 3: the buckets' distinct records moved down to close the gaps
  // (each bucket lands at or before where it was: in order, nothing is
  // overwritten before it moves).
  out.BucketStart.assign(buckets + 1, 0);
  for (std::size_t k = 0; k < buckets; ++k)
  {
    out.BucketStart[k + 1] = out.BucketStart[k] + kept[k];
    if (out.BucketStart[k] < start[k]) // (std::move may not write onto its own source's start)
    {
      const auto from = out.Records.begin() + static_cast<std::ptrdiff_t>(start[k]);
      std::move(from, from + static_cast<std::ptrdiff_t>(kept[k]),
        out.Records.begin() + static_cast<std::ptrdiff_t>(out.BucketStart[k]));
    }
  }
  out.Records.resize(out.BucketStart[buckets]);
  return true;
}

} // namespace tpc
