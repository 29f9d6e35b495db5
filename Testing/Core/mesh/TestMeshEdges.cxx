// The edge table (MeshEdges.h), the genus from the Euler characteristic, and
// the releasable arrays the output mesh is written into (ReleasableArray.h).
#include "MeshBuilders.h"
#include "MeshEdges.h"
#include "ReleasableArray.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

TEST(MeshEdges, EveryUseOfAnEdgeIsConsecutiveAndSorted)
{
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, 1.0, 0.3, 9, 7);
  const auto& triangles = torus.Triangles();
  std::vector<tpc::EdgeUse> uses;
  ASSERT_TRUE(tpc::BuildEdgeTable(triangles.data(), triangles.size(), uses));
  ASSERT_EQ(uses.size(), 3 * triangles.size());
  EXPECT_TRUE(std::is_sorted(uses.begin(), uses.end()));
  std::size_t edges = 0;
  tpc::ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    ++edges;
    ASSERT_EQ(count, 2u); // a closed manifold
    // Walked once each way (consistently oriented).
    EXPECT_NE(uses[first].Ascending, uses[first + 1].Ascending);
    for (std::size_t k = first; k < first + count; ++k)
    {
      const tpc::Triangle& t = triangles[uses[k].Triangle];
      const std::uint32_t from = t[uses[k].Corner], to = t[(uses[k].Corner + 1) % 3];
      EXPECT_EQ(tpc::EdgeKey(from, to), uses[k].Key);
      EXPECT_EQ(uses[k].Ascending, from < to);
      EXPECT_EQ(tpc::EdgeLow(uses[k].Key), std::min(from, to));
      EXPECT_EQ(tpc::EdgeHigh(uses[k].Key), std::max(from, to));
    }
  });
  EXPECT_EQ(edges, 3 * triangles.size() / 2);
}

TEST(MeshEdges, TableIsTheSameInParallelAndAbortStopsIt)
{
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0, 0, 0 }, 1.0, 3);
  const auto& triangles = sphere.Triangles();
  std::vector<tpc::EdgeUse> sequential, parallel;
  ASSERT_TRUE(tpc::BuildEdgeTable(triangles.data(), triangles.size(), sequential));
  // Ranges handed out in small, uneven pieces, as threads would take them.
  const tpc::ParallelFor pieces = [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    for (std::size_t begin = 0; begin < count; begin += 7)
    {
      body(begin, std::min(count, begin + 7));
    }
  };
  ASSERT_TRUE(tpc::BuildEdgeTable(triangles.data(), triangles.size(), parallel, pieces));
  ASSERT_EQ(sequential.size(), parallel.size());
  for (std::size_t i = 0; i < sequential.size(); ++i)
  {
    EXPECT_EQ(sequential[i].Key, parallel[i].Key);
    EXPECT_EQ(sequential[i].Triangle, parallel[i].Triangle);
    EXPECT_EQ(sequential[i].Corner, parallel[i].Corner);
  }
  EXPECT_FALSE(tpc::BuildEdgeTable(triangles.data(), triangles.size(), parallel, tpc::SequentialFor,
    [](double) { return true; }));
}

TEST(MeshEdges, GenusFromEulerCharacteristic)
{
  EXPECT_EQ(tpc::GenusFromEuler(1, 2), 0);    // sphere
  EXPECT_EQ(tpc::GenusFromEuler(1, 0), 1);    // torus
  EXPECT_EQ(tpc::GenusFromEuler(2, 2), 1);    // sphere + torus
  EXPECT_EQ(tpc::GenusFromEuler(3, -4), 5);   // three components, genera summing to 5
  EXPECT_EQ(tpc::GenusFromEuler(1, 1), -1);   // odd: no closed orientable surface
  EXPECT_EQ(tpc::GenusFromEuler(1, 4), -1);   // more than a sphere per component
}

TEST(ReleasableArray, BehavesAsAVectorAndReleasesItsMemory)
{
  tpc::ReleasableArray<tpc::Vec3> a = { { 1, 2, 3 }, { 4, 5, 6 } };
  for (int i = 0; i < 1000; ++i)
  {
    a.push_back(a[static_cast<std::size_t>(i)]); // (an element of the array itself, across growth)
  }
  ASSERT_EQ(a.size(), 1002u);
  EXPECT_EQ(a[1001][0], 4.0);
  EXPECT_EQ(a[1000][2], 3.0);
  tpc::ReleasableArray<tpc::Vec3> copy = a;
  ASSERT_EQ(copy.size(), a.size());
  EXPECT_EQ(copy[1001][0], 4.0);
  copy[0][0] = -1.0;
  EXPECT_EQ(a[0][0], 1.0); // a copy, not a view
  tpc::ReleasableArray<tpc::Vec3> moved = std::move(copy);
  EXPECT_EQ(moved.size(), 1002u);
  EXPECT_EQ(moved[0][0], -1.0);
  moved.resize(1005);
  EXPECT_EQ(moved[1004][1], 0.0); // new values are zero
  const std::vector<tpc::Vec3> v = moved.ToVector();
  EXPECT_EQ(v.size(), 1005u);
  EXPECT_EQ(v[1][2], 6.0);
  tpc::Vec3* data = moved.Release();
  EXPECT_TRUE(moved.empty());
  EXPECT_EQ(data[1][1], 5.0);
  std::free(data); // (the new owner frees it so)
}
