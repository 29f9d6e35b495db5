// Each case of the paper's Fig. 2 (a)-(d) is detected on a unit cell, and
// edge crossings are counted exactly (tangency is never "proven simple").
#include "ComplexCellTest.h"
#include "CubeTopology.h"
#include "EdgeCrossings.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

using tpc::Box3;
using tpc::RegionSign;
using tpc::SplitReason;
using tpctest::SceneBuilder;

namespace
{
const Box3 UnitCell{ { 0, 0, 0 }, { 1, 1, 1 } };

unsigned CornerMask(const tpc::CsgExpressionPtr& e, const std::vector<tpc::Quadric>& prims)
{
  unsigned mask = 0;
  for (int c = 0; c < 8; ++c)
  {
    mask |= e->IsInside(UnitCell.Corner(c), prims) ? (1u << c) : 0u;
  }
  return mask;
}
} // namespace

TEST(ComplexCell, ComplexVoxelFig2a)
{
  // A small sphere strictly inside the cell: no corner sees it.
  SceneBuilder b;
  const auto e = b.Finish(b.Sphere({ 0.5, 0.5, 0.5 }, 0.2));
  const auto& prims = b.Scene.Primitives;
  const unsigned mask = CornerMask(e, prims);
  EXPECT_EQ(mask, 0u);
  EXPECT_EQ(tpc::ProveConstantSign(e, prims, UnitCell, 2), RegionSign::Mixed);
  EXPECT_EQ(tpc::ComplexVoxelOrFaceTest({ e, prims, UnitCell, mask }), SplitReason::ComplexVoxel);
  // Far from the sphere the same cell is proven empty.
  const Box3 far{ { 2, 2, 2 }, { 3, 3, 3 } };
  EXPECT_EQ(tpc::ProveConstantSign(e, prims, far, 0), RegionSign::Outside);
}

TEST(ComplexCell, ComplexFaceFig2b)
{
  // Lower half inside (sign change in the cell) plus a cap poking through the
  // top face, whose corners are all outside.
  SceneBuilder b;
  const auto e = b.Finish(SceneBuilder::Union(
    { b.Box({ -1, -1, -1 }, { 2, 2, 0.3 }), b.Sphere({ 0.5, 0.5, 1.1 }, 0.2) }));
  const auto& prims = b.Scene.Primitives;
  const unsigned mask = CornerMask(e, prims);
  EXPECT_EQ(mask, 0x0Fu); // z = 0 corners inside
  EXPECT_EQ(tpc::SignAmbiguityTest(mask), SplitReason::None);
  EXPECT_EQ(tpc::ComplexVoxelOrFaceTest({ e, prims, UnitCell, mask }), SplitReason::ComplexFace);

  // Without the cap the cell is not complex.
  SceneBuilder plain;
  const auto p = plain.Finish(plain.Box({ -1, -1, -1 }, { 2, 2, 0.3 }));
  EXPECT_EQ(tpc::ComplexVoxelOrFaceTest({ p, plain.Scene.Primitives, UnitCell, CornerMask(p, plain.Scene.Primitives) }),
    SplitReason::None);
  EXPECT_EQ(tpc::ComplexEdgeTest({ p, plain.Scene.Primitives, UnitCell, CornerMask(p, plain.Scene.Primitives) }),
    SplitReason::None);
}

TEST(ComplexCell, ComplexEdgeFig2c)
{
  // A sphere centred on the edge (0,0,1)-(1,0,1) crosses it twice.
  SceneBuilder b;
  const auto e = b.Finish(SceneBuilder::Union(
    { b.Box({ -1, -1, -1 }, { 2, 2, 0.3 }), b.Sphere({ 0.5, 0.0, 1.0 }, 0.2) }));
  const auto& prims = b.Scene.Primitives;
  const unsigned mask = CornerMask(e, prims);
  EXPECT_EQ(tpc::ComplexEdgeTest({ e, prims, UnitCell, mask }), SplitReason::ComplexEdge);
  const tpc::EdgeCrossingCount twice =
    tpc::CountEdgeCrossings(e, prims, { 0, 0, 1 }, { 1, 0, 1 }, 0, false, false);
  EXPECT_TRUE(twice.Proven);
  EXPECT_EQ(twice.Count, 2);
  // A vertical edge crosses the box top once.
  const tpc::EdgeCrossingCount once =
    tpc::CountEdgeCrossings(e, prims, { 1, 1, 0 }, { 1, 1, 1 }, 2, true, false);
  EXPECT_TRUE(once.Proven);
  EXPECT_EQ(once.Count, 1);
}

TEST(ComplexCell, TangentEdgeIsNeverProvenSimple)
{
  // The edge y = 0.3, z = 0 touches the sphere of radius 0.3 at one point:
  // E meets the edge without a sign change, which MC cannot represent.
  SceneBuilder b;
  const auto e = b.Finish(b.Sphere({ 0.5, 0.0, 0.0 }, 0.3));
  const tpc::EdgeCrossingCount touch =
    tpc::CountEdgeCrossings(e, b.Scene.Primitives, { 0, 0.3, 0 }, { 1, 0.3, 0 }, 0, false, false, 30);
  EXPECT_FALSE(touch.Proven && touch.Count == 0);
}

TEST(ComplexCell, FaceAndVoxelAmbiguityFig2d)
{
  // Two small spheres at body-diagonal corners: voxel ambiguity.
  SceneBuilder b;
  const auto e = b.Finish(
    SceneBuilder::Union({ b.Sphere({ 0, 0, 0 }, 0.3), b.Sphere({ 1, 1, 1 }, 0.3) }));
  const unsigned mask = CornerMask(e, b.Scene.Primitives);
  EXPECT_EQ(mask, (1u << 0) | (1u << 7));
  EXPECT_EQ(tpc::SignAmbiguityTest(mask), SplitReason::VoxelAmbiguity);

  // Two spheres at face-diagonal corners of the z = 0 face: face ambiguity.
  SceneBuilder f;
  const auto g = f.Finish(
    SceneBuilder::Union({ f.Sphere({ 0, 0, 0 }, 0.3), f.Sphere({ 1, 1, 0 }, 0.3) }));
  const unsigned fmask = CornerMask(g, f.Scene.Primitives);
  EXPECT_EQ(fmask, (1u << 0) | (1u << 3));
  EXPECT_EQ(tpc::SignAmbiguityTest(fmask), SplitReason::FaceAmbiguity);

  // All 256 configurations against an independent oracle: a configuration is
  // unambiguous iff its inside corners and its outside corners each form an
  // edge-connected set (empty counts as connected).
  auto connected = [](unsigned set) {
    if (set == 0)
    {
      return true;
    }
    unsigned seen = set & (~set + 1); // lowest corner
    for (bool grew = true; grew;)
    {
      grew = false;
      for (int c = 0; c < 8; ++c)
      {
        if (!((seen >> c) & 1))
        {
          continue;
        }
        for (int a = 0; a < 3; ++a)
        {
          const int n = c ^ (1 << a);
          if (((set >> n) & 1) && !((seen >> n) & 1))
          {
            seen |= 1u << n;
            grew = true;
          }
        }
      }
    }
    return seen == set;
  };
  int ambiguous = 0;
  for (unsigned m = 0; m < 256; ++m)
  {
    const bool expected = !(connected(m) && connected(0xFFu & ~m));
    ASSERT_EQ(tpc::SignAmbiguityTest(m) != SplitReason::None, expected) << "mask " << m;
    ambiguous += expected ? 1 : 0;
  }
  EXPECT_GT(ambiguous, 0);
}
