// ScratchPool: a leased object is the holder's alone, and an object given
// back is handed out again with its memory (what the pool is for).
#include "ScratchPool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

TEST(ScratchPool, AReturnedObjectIsReusedWithItsMemory)
{
  tpc::ScratchPool<std::vector<int>> pool;
  const std::vector<int>* first = nullptr;
  const int* data = nullptr;
  {
    tpc::ScratchPool<std::vector<int>>::Lease lease(pool);
    lease->assign(1000, 7);
    first = &*lease;
    data = lease->data();
  }
  tpc::ScratchPool<std::vector<int>>::Lease again(pool);
  EXPECT_EQ(&*again, first);
  again->clear();
  EXPECT_GE(again->capacity(), 1000u); // (the buffer is still there)
  again->resize(1000);
  EXPECT_EQ(again->data(), data);
}

TEST(ScratchPool, LeasesHeldAtOnceAreDistinct)
{
  tpc::ScratchPool<int> pool;
  tpc::ScratchPool<int>::Lease a(pool);
  tpc::ScratchPool<int>::Lease b(pool);
  EXPECT_NE(&*a, &*b);
}

TEST(ScratchPool, NoTwoThreadsHoldTheSameObject)
{
  // Each object counts its holders; a second holder at once would be seen.
  struct Scratch
  {
    std::atomic<int> Holders{ 0 };
    long Uses = 0;
  };
  tpc::ScratchPool<Scratch> pool;
  std::atomic<bool> shared{ false };
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
  {
    threads.emplace_back([&] {
      for (int i = 0; i < 2000; ++i)
      {
        tpc::ScratchPool<Scratch>::Lease lease(pool);
        if (lease->Holders.fetch_add(1) != 0)
        {
          shared = true;
        }
        ++lease->Uses;
        lease->Holders.fetch_sub(1);
      }
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  EXPECT_FALSE(shared);
}
