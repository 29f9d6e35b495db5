// CSG normalization and pruning: pruned expressions classify every point of
// the box exactly as the full expression does; differences behave as A and
// not B; bounds follow the CSG.
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <random>

using tpc::Box3;
using tpc::CsgExpression;
using tpc::RegionSign;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
/// (box ∩ sphere) − (three cylinders): the classic CSG tree.
tpc::CsgExpressionPtr ClassicCsg(SceneBuilder& b)
{
  const auto body = SceneBuilder::Intersection(
    { b.Box({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 }), b.Sphere({ 0, 0, 0 }, 0.68) });
  const auto holes = SceneBuilder::Union({ b.Cylinder({ 0, 0, 0 }, { 1, 0, 0 }, 0.25),
    b.Cylinder({ 0, 0, 0 }, { 0, 1, 0 }, 0.25), b.Cylinder({ 0, 0, 0 }, { 0, 0, 1 }, 0.25) });
  return b.Finish(SceneBuilder::Difference({ body, holes }));
}
} // namespace

TEST(CsgExpression, DifferenceIsInsideFirstAndOutsideOthers)
{
  SceneBuilder b;
  const auto a = b.Sphere({ 0, 0, 0 }, 1.0);
  const auto c = b.Sphere({ 0.5, 0, 0 }, 0.5);
  const auto e = b.Finish(SceneBuilder::Difference({ a, c }));
  const auto& prims = b.Scene.Primitives;
  EXPECT_TRUE(e->IsInside({ -0.5, 0, 0 }, prims));
  EXPECT_FALSE(e->IsInside({ 0.5, 0, 0 }, prims));
  EXPECT_FALSE(e->IsInside({ 1.5, 0, 0 }, prims));
  // Normalized: one intersection node over a leaf and a complemented leaf.
  const auto leaves = e->Leaves();
  ASSERT_EQ(leaves.size(), 2u);
  EXPECT_EQ(leaves[0].Sigma + leaves[1].Sigma, 0);
}

TEST(CsgExpression, PruningPreservesTheSignEverywhereInTheBox)
{
  SceneBuilder b;
  const auto full = ClassicCsg(b);
  const auto& prims = b.Scene.Primitives;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-0.8, 0.8), s(0.01, 0.4);
  int mixed = 0, constant = 0, smaller = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    Box3 box;
    const double size = s(rng);
    for (int a = 0; a < 3; ++a)
    {
      box.lo[a] = u(rng);
      box.hi[a] = box.lo[a] + size;
    }
    const auto pruned = CsgExpression::Prune(full, box, prims);
    std::uniform_real_distribution<double> t(0.0, 1.0);
    for (int k = 0; k < 30; ++k)
    {
      Vec3 p = k < 8 ? box.Corner(k) : Vec3();
      if (k >= 8)
      {
        for (int a = 0; a < 3; ++a)
        {
          p[a] = box.lo[a] + t(rng) * size;
        }
      }
      const bool in = full->IsInside(p, prims);
      if (pruned.Sign == RegionSign::Mixed)
      {
        ASSERT_EQ(pruned.Expression->IsInside(p, prims), in);
      }
      else
      {
        ASSERT_EQ(pruned.Sign == RegionSign::Inside, in);
      }
    }
    if (pruned.Sign == RegionSign::Mixed)
    {
      ++mixed;
      smaller += pruned.Expression->NodeCount() < full->NodeCount() ? 1 : 0;
    }
    else
    {
      ++constant;
    }
  }
  // The test exercised both outcomes, and pruning removed leaves.
  EXPECT_GT(mixed, 100);
  EXPECT_GT(constant, 100);
  EXPECT_GT(smaller, 100);
}

TEST(CsgExpression, BoundsFollowTheCsg)
{
  SceneBuilder b;
  const auto box = b.Box({ 0, 0, 0 }, { 1, 2, 3 });
  const auto sphere = b.Sphere({ 5, 5, 5 }, 1.0);
  const auto uni = SceneBuilder::Union({ box, sphere });
  const auto inter = SceneBuilder::Intersection({ box, b.Sphere({ 0, 0, 0 }, 0.5) });
  const auto diff = SceneBuilder::Difference({ box, sphere });
  const auto& prims = b.Scene.Primitives;

  const tpc::SolidBounds u = uni.Bounds(prims);
  ASSERT_TRUE(u.Bounded());
  EXPECT_NEAR(u.Box.lo[0], 0.0, 1e-9);
  EXPECT_NEAR(u.Box.hi[2], 6.0, 1e-9);
  const tpc::SolidBounds i = inter.Bounds(prims);
  EXPECT_NEAR(i.Box.hi[0], 0.5, 1e-9);
  EXPECT_NEAR(i.Box.lo[0], 0.0, 1e-9);
  const tpc::SolidBounds d = diff.Bounds(prims);
  EXPECT_NEAR(d.Box.hi[1], 2.0, 1e-9);
  EXPECT_FALSE(SceneBuilder::Union({ box, b.Cylinder({ 0, 0, 0 }, { 0, 0, 1 }, 1) }).Bounds(prims).Bounded());
}
