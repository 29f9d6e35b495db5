// GatherDistinct: every key emitted lands once in its bucket, as the first of
// its repeats by `less`, the buckets one after the other - the same records
// whatever order the blocks and buckets run in.
#include "DistinctRecords.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <thread>
#include <utility>
#include <vector>

namespace
{
using Record = std::pair<std::uint32_t, std::uint32_t>; // (key, tag)
using Emitter = std::function<std::vector<Record>(std::size_t block)>;

constexpr std::size_t Blocks = 16, Buckets = 8;

/// Many repeats: each key twice within a block (tags differing) and across
/// blocks (a later block's tags smaller); no key is 3 or 6 modulo 8, so two
/// buckets stay empty. The buckets shrink to a sixth: their records move
/// far down.
std::vector<Record> ManyRepeats(std::size_t b)
{
  std::vector<Record> records;
  for (std::uint32_t i = 0; i < 40; ++i)
  {
    const std::uint32_t key = (static_cast<std::uint32_t>(b) * 7 + (i % 20) * 13) % 97;
    if (key % 8 != 3 && key % 8 != 6)
    {
      records.emplace_back(key, 1000 - static_cast<std::uint32_t>(b) * 10 + i % 3);
    }
  }
  return records;
}

/// Few repeats: distinct keys but key 0, emitted by every block (its
/// smallest tag by the last, and twice there): the buckets after the first
/// move down by less than they hold, onto their own records.
std::vector<Record> FewRepeats(std::size_t b)
{
  std::vector<Record> records;
  for (std::uint32_t i = 1; i < 40; ++i)
  {
    records.emplace_back(static_cast<std::uint32_t>(b) * 40 + i, 7);
  }
  const auto tag = static_cast<std::uint32_t>(Blocks - b);
  records.emplace_back(0, tag + 1);
  records.emplace_back(0, tag);
  return records;
}

tpc::BucketedRecords<Record> Gather(const Emitter& emitted, const tpc::ParallelFor& parallelFor)
{
  tpc::BucketedRecords<Record> out;
  const bool done = tpc::GatherDistinct<Record>(Blocks, Buckets,
    [&](std::size_t b, const auto& emit) {
      for (const Record& r : emitted(b))
      {
        emit(r);
      }
    },
    [](const Record& r) { return static_cast<std::size_t>(r.first % Buckets); }, std::less<>(),
    [](const Record& x, const Record& y) { return x.first == y.first; }, parallelFor, nullptr, out);
  EXPECT_TRUE(done);
  return out;
}

void ExpectEachKeyOnceAsItsFirst(const Emitter& emitted)
{
  std::map<std::uint32_t, std::uint32_t> smallestTag;
  for (std::size_t b = 0; b < Blocks; ++b)
  {
    for (const Record& r : emitted(b))
    {
      const auto [at, added] = smallestTag.emplace(r.first, r.second);
      at->second = added ? r.second : std::min(at->second, r.second);
    }
  }
  const tpc::BucketedRecords<Record> out = Gather(emitted, tpc::SequentialFor);
  ASSERT_EQ(out.BucketStart.size(), Buckets + 1);
  EXPECT_EQ(out.BucketStart.front(), 0u);
  EXPECT_EQ(out.BucketStart.back(), out.Records.size());
  EXPECT_EQ(out.Records.size(), smallestTag.size());
  std::map<std::uint32_t, std::uint32_t> found;
  for (std::size_t k = 0; k < Buckets; ++k)
  {
    ASSERT_LE(out.BucketStart[k], out.BucketStart[k + 1]);
    for (std::size_t i = out.BucketStart[k]; i < out.BucketStart[k + 1]; ++i)
    {
      const Record& r = out.Records[i];
      EXPECT_EQ(r.first % Buckets, k) << "record " << i;
      if (i > out.BucketStart[k])
      {
        EXPECT_LT(out.Records[i - 1].first, r.first) << "bucket " << k << " sorted, each key once";
      }
      found.emplace(r.first, r.second);
    }
  }
  EXPECT_EQ(found, smallestTag);
}
} // namespace

TEST(DistinctRecords, EachKeyLandsOnceInItsBucketAsTheFirstByOrder)
{
  ExpectEachKeyOnceAsItsFirst(ManyRepeats);
  ExpectEachKeyOnceAsItsFirst(FewRepeats);
  const tpc::BucketedRecords<Record> many = Gather(ManyRepeats, tpc::SequentialFor);
  for (const std::size_t empty : { 3, 6 })
  {
    EXPECT_EQ(many.BucketStart[empty], many.BucketStart[empty + 1]) << "bucket " << empty << " holds no key";
  }
}

TEST(DistinctRecords, TheSameInParallelAndInAnyOrder)
{
  // Ranges of one item, run last to first; and two threads at once.
  const tpc::ParallelFor backwards = [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    for (std::size_t i = count; i-- > 0;)
    {
      body(i, i + 1);
    }
  };
  const tpc::ParallelFor twoThreads = [](std::size_t count,
                                        const std::function<void(std::size_t, std::size_t)>& body) {
    std::thread other([&] { body(count / 2, count); });
    body(0, count / 2);
    other.join();
  };
  for (const Emitter& emitted : { Emitter(ManyRepeats), Emitter(FewRepeats) })
  {
    const tpc::BucketedRecords<Record> sequential = Gather(emitted, tpc::SequentialFor);
    for (const tpc::ParallelFor& parallelFor : { backwards, twoThreads })
    {
      const tpc::BucketedRecords<Record> out = Gather(emitted, parallelFor);
      EXPECT_EQ(out.Records, sequential.Records);
      EXPECT_EQ(out.BucketStart, sequential.BucketStart);
    }
  }
}
