// Face refinement (FaceRefinement.h) and the exact edge crossings the
// extraction places (EdgeCrossings.h).
#include "CellSignCache.h"
#include "ComplexCellCriterion.h"
#include "EdgeCrossings.h"
#include "FaceRefinement.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using tpc::FaceTile;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
/// A unit root cell with a lattice of 2^10 spacings.
tpc::RootGrid UnitGrid()
{
  return tpctest::SingleRoot({ 0, 0, 0 }, 1.0, 10);
}
constexpr std::uint32_t Side = 1024;

/// Tiles that cover [0, Side]^2 exactly: inside it, of total area Side^2, no
/// two overlapping.
void ExpectTiling(const std::vector<FaceTile>& tiles)
{
  std::uint64_t area = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i)
  {
    const FaceTile& t = tiles[i];
    ASSERT_TRUE(t.U0 < t.U1 && t.V0 < t.V1 && t.U1 <= Side && t.V1 <= Side);
    area += std::uint64_t(t.U1 - t.U0) * (t.V1 - t.V0);
    for (std::size_t j = i + 1; j < tiles.size(); ++j)
    {
      const FaceTile& o = tiles[j];
      ASSERT_FALSE(t.U0 < o.U1 && o.U0 < t.U1 && t.V0 < o.V1 && o.V0 < t.V1) << i << " overlaps " << j;
    }
  }
  EXPECT_EQ(area, std::uint64_t(Side) * Side);
}
} // namespace

TEST(FaceRefinement, TilesCoverTheFaceAndEachPassesTheFaceTests)
{
  // The sharp wedge of ComplexCell.SharpCreaseIsResolvedByRefiningFaces,
  // on the face z = 1/2: wherever its crease pierces the face, the face is
  // tiled so that every tile passes on its own corners.
  const tpc::RootGrid grid = UnitGrid();
  int refined = 0;
  for (int k = 0; k < 40; ++k)
  {
    SceneBuilder b;
    const Vec3 through{ 0.5 + 0.4 * std::sin(1.3 * k), 0.5 + 0.3 * std::cos(0.7 * k), 0.5 };
    const auto e = b.Finish(SceneBuilder::Union({ b.Add(tpc::Quadric::Plane(through, { 1.0, 0.3, 0.15 })),
      b.Add(tpc::Quadric::Plane(through, { -1.0, 0.35, 0.1 })) }));
    const auto& prims = b.Scene.Primitives;
    tpc::LatticeSignTable global;
    tpc::CellSignCache signs(global, grid, *e, prims);
    const tpc::FaceRefinementResult r =
      tpc::RefineFace(e, prims, grid, 2, Side / 2, { 0, 0, Side, Side }, 10, signs);
    ASSERT_EQ(r.Failure, tpc::SplitReason::None) << k;
    ExpectTiling(r.Tiles);
    refined += r.Tiles.size() > 1 ? 1 : 0;
    for (const FaceTile& t : r.Tiles)
    {
      tpc::Box3 face;
      face.lo = { grid.Coordinate(0, t.U0), grid.Coordinate(1, t.V0), 0.5 };
      face.hi = { grid.Coordinate(0, t.U1), grid.Coordinate(1, t.V1), 0.5 };
      const bool inside[4] = { e->IsInside({ face.lo[0], face.lo[1], 0.5 }, prims),
        e->IsInside({ face.hi[0], face.lo[1], 0.5 }, prims), e->IsInside({ face.hi[0], face.hi[1], 0.5 }, prims),
        e->IsInside({ face.lo[0], face.hi[1], 0.5 }, prims) };
      EXPECT_EQ(tpc::FaceCompatibilityTest(e, prims, face, 2, inside), tpc::SplitReason::None);
    }
    // Every tile corner was sampled, exactly, and is kept for the table.
    for (const FaceTile& t : r.Tiles)
    {
      for (int c = 0; c < 4; ++c)
      {
        const tpc::PointKey key = tpc::TileCorner(2, Side / 2, t, c);
        const auto it = std::find_if(signs.NewSigns().begin(), signs.NewSigns().end(),
          [key](const auto& sign) { return sign.first == key; });
        ASSERT_NE(it, signs.NewSigns().end());
        EXPECT_EQ(it->second, e->IsInside(grid.Point(key), prims));
      }
    }
  }
  EXPECT_GT(refined, 10);
}

TEST(FaceRefinement, GivesUpWithinItsLevelsOnATangency)
{
  // A sphere touching the face z = 1/2 from below at its centre: the face
  // meets the surface at a point without a sign change, at every level (a
  // complex face, then tiles whose edges end at the touching point).
  const tpc::RootGrid grid = UnitGrid();
  SceneBuilder b;
  const auto e = b.Finish(b.Sphere({ 0.5, 0.5, 0.3 }, 0.2));
  tpc::LatticeSignTable global;
  tpc::CellSignCache signs(global, grid, *e, b.Scene.Primitives);
  const tpc::FaceRefinementResult whole =
    tpc::RefineFace(e, b.Scene.Primitives, grid, 2, Side / 2, { 0, 0, Side, Side }, 0, signs);
  EXPECT_TRUE(whole.Tiles.empty());
  EXPECT_EQ(whole.Failure, tpc::SplitReason::ComplexFace);
  const tpc::FaceRefinementResult refined =
    tpc::RefineFace(e, b.Scene.Primitives, grid, 2, Side / 2, { 0, 0, Side, Side }, 3, signs);
  EXPECT_TRUE(refined.Tiles.empty());
  EXPECT_TRUE(refined.Failure == tpc::SplitReason::ComplexFace || refined.Failure == tpc::SplitReason::ComplexEdge)
    << tpc::SplitReasonName(refined.Failure);
  // The circle where the sphere crosses z = 1/4 lies inside that face, away
  // from its corners: refining the face resolves it.
  const tpc::FaceRefinementResult circle =
    tpc::RefineFace(e, b.Scene.Primitives, grid, 2, Side / 4, { 0, 0, Side, Side }, 3, signs);
  EXPECT_EQ(circle.Failure, tpc::SplitReason::None);
  EXPECT_GT(circle.Tiles.size(), 1u);
  ExpectTiling(circle.Tiles);
}

TEST(EdgeCrossings, FoundOnTheExactSurfaceInsideTheSegment)
{
  // A sphere, a CSG union (regula falsi on the field), a difference, and a
  // mesh (exact bisection, or the crossed triangle's plane).
  SceneBuilder b;
  const auto sphere = b.Finish(b.Sphere({ 0.3, 0.2, 0.1 }, 0.45));
  const Vec3 a{ 0.3, 0.2, 0.1 }, z{ 0.3, 0.2, 1.0 };
  const Vec3 p = tpc::FindEdgeCrossing(*sphere, b.Scene.Primitives, a, z, true);
  EXPECT_NEAR(p[2], 0.55, 1e-13);
  EXPECT_EQ(p[0], 0.3);
  EXPECT_EQ(p[1], 0.2);

  SceneBuilder u;
  const auto both = u.Finish(SceneBuilder::Difference({ SceneBuilder::Union({ u.Sphere({ 0, 0, 0 }, 0.5),
    u.Sphere({ 0.6, 0, 0 }, 0.4) }), u.Sphere({ 0.9, 0, 0 }, 0.05) }));
  // Inside the union at 0.5, in the subtracted sphere (outside) at 0.9: its
  // wall at 0.85 is the one crossing.
  const Vec3 q = tpc::FindEdgeCrossing(*both, u.Scene.Primitives, { 0.5, 0, 0 }, { 0.9, 0, 0 }, true);
  EXPECT_NEAR(q[0], 0.85, 1e-12);

  SceneBuilder m;
  const auto cube = m.Finish(m.Mesh(tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 })));
  const Vec3 s = tpc::FindEdgeCrossing(*cube, m.Scene.Primitives, { 0.25, 0.5, 0.5 }, { 0.25, 0.5, 1.5 }, true);
  EXPECT_NEAR(s[2], 1.0, 1e-12);
  EXPECT_EQ(s[0], 0.25);
}
