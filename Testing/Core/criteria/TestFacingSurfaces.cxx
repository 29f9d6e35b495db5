// Surfaces facing each other closer than the finest cell (FacingSurfaces.h):
// which cells are recognised, and that the subdivision stops them at the
// tolerance's size instead of refining an area to the depth limit.
#include "CoreContour.h"
#include "FacingSurfaces.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

using tpc::Box3;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
/// HasFacingSurfaces on the scene's expression pruned to `cell` (as the
/// subdivision calls it); false when the cell has one sign.
bool Facing(const tpc::ImplicitScene& scene, const Box3& cell, double gap)
{
  const auto pruned = tpc::CsgExpression::Prune(scene.Expression, cell, scene.Primitives);
  return pruned.Sign == tpc::RegionSign::Mixed &&
    tpc::HasFacingSurfaces(*pruned.Expression, scene.Primitives, cell, gap);
}

Box3 CellAround(const Vec3& c, double half)
{
  return { c - Vec3(half, half, half), c + Vec3(half, half, half) };
}
} // namespace

TEST(FacingSurfaces, BoxesSharingAFaceFaceEachOther)
{
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Box({ 0, 0, 0 }, { 1, 1, 1 }), b.Box({ 1, 0, 0 }, { 2, 1, 1 }) }));
  EXPECT_TRUE(Facing(b.Scene, CellAround({ 1.01, 0.5, 0.5 }, 0.05), 1e-6));
  // Away from the shared face only one box's faces are in the cell.
  EXPECT_FALSE(Facing(b.Scene, CellAround({ 0.5, 0.99, 0.5 }, 0.05), 1e-6));
}

TEST(FacingSurfaces, OnlySurfacesInOnePlaneTouch)
{
  // Boxes sharing a face lie in one plane there (no other lattice placement
  // separates them); spheres 1e-7 apart only face each other closely.
  auto touching = [](const tpc::ImplicitScene& scene, const Box3& cell) {
    const auto pruned = tpc::CsgExpression::Prune(scene.Expression, cell, scene.Primitives);
    bool touch = false;
    const bool facing = tpc::HasFacingSurfaces(*pruned.Expression, scene.Primitives, cell, 1e-4, &touch);
    return facing ? (touch ? 2 : 1) : 0;
  };
  SceneBuilder boxes;
  boxes.Finish(SceneBuilder::Union({ boxes.Box({ 0, 0, 0 }, { 1, 1, 1 }), boxes.Box({ 1, 0, 0 }, { 2, 1, 1 }) }));
  EXPECT_EQ(touching(boxes.Scene, CellAround({ 1.0013, 0.5, 0.5 }, 0.003)), 2);
  SceneBuilder spheres;
  spheres.Finish(SceneBuilder::Union(
    { spheres.Sphere({ -0.5, 0.01, 0 }, 0.5), spheres.Sphere({ 0.5 + 1e-7, 0.01, 0 }, 0.5) }));
  EXPECT_EQ(touching(spheres.Scene, CellAround({ 0.0003, 0.0101, 0.0002 }, 0.0005)), 1);
}

TEST(FacingSurfaces, AGapWiderThanTheFinestCellIsNotFacing)
{
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Box({ 0, 0, 0 }, { 1, 1, 1 }), b.Box({ 1.001, 0, 0 }, { 2, 1, 1 }) }));
  const Box3 cell = CellAround({ 1.0005, 0.5, 0.5 }, 0.05);
  EXPECT_FALSE(Facing(b.Scene, cell, 0.0009));
  EXPECT_TRUE(Facing(b.Scene, cell, 0.0011));
}

TEST(FacingSurfaces, CoincidentFacesOnTheSameSideAreNotFacing)
{
  // A box cut by a half-space through its own face: both surfaces point the
  // same way (FilterErrors.BoxFacesOnTheBoundsAreResolved).
  SceneBuilder b;
  b.Finish(SceneBuilder::Intersection(
    { b.Box({ 0, 0, 0 }, { 1, 1, 1 }), b.Add(tpc::Quadric::Plane({ 1, 0, 0 }, { 1, 0, 0 })) }));
  EXPECT_FALSE(Facing(b.Scene, CellAround({ 1.01, 0.5, 0.5 }, 0.05), 1e-6));
}

TEST(FacingSurfaces, CurvedSurfacesFaceEachOtherOnlyInCellsSmallEnoughToBeFlat)
{
  // A spherical shell 1e-9 thick: over a cell of width w the spheres depart
  // from their tangent planes by about w^2 / (2 r).
  SceneBuilder b;
  b.Finish(SceneBuilder::Difference({ b.Sphere({ 0, 0, 0 }, 0.5 + 1e-9), b.Sphere({ 0, 0, 0 }, 0.5) }));
  EXPECT_TRUE(Facing(b.Scene, CellAround({ 0, 0, 0.5 }, 0.001), 3e-5));
  EXPECT_FALSE(Facing(b.Scene, CellAround({ 0, 0, 0.5 }, 0.05), 3e-5));
}

TEST(FacingSurfaces, MeshFacesAreFacingSurfacesToo)
{
  // A cube mesh resting on a box.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Mesh(tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 })),
    b.Box({ 0, 0, -1 }, { 1, 1, 0 }) }));
  EXPECT_TRUE(Facing(b.Scene, CellAround({ 0.5, 0.5, 0.001 }, 0.02), 1e-6));
  // A plate of one mesh thinner than the finest cell: its two sides.
  SceneBuilder plate;
  plate.Finish(plate.Mesh(tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1e-8 })));
  EXPECT_TRUE(Facing(plate.Scene, CellAround({ 0.5, 0.5, 0.0 }, 0.02), 1e-6));
  EXPECT_FALSE(Facing(plate.Scene, CellAround({ 0.5, 0.5, 0.0 }, 0.02), 1e-9));
}

TEST(FacingSurfaces, BoxesSharingAFaceStopAtTheToleranceSizeWithoutAGuarantee)
{
  // Refining the shared face would quadruple the cells per level down to
  // MaximumDepth (hours at 16); it stops where the tolerance is met.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Box({ 0, 0, 0 }, { 1, 1, 1 }), b.Box({ 1, 0, 0 }, { 2, 1, 1 }) }));
  const Box3 bounds{ { 0, 0, 0 }, { 2, 1, 1 } };
  tpc::SubdivisionParameters p;
  p.HausdorffTolerance = 0.02 * bounds.Diagonal();
  p.MaximumDepth = 16;
  const tpc::PlacedSubdivision placed =
    tpc::RunOnBestLatticePlacement(b.Scene, tpctest::GrownDomain(bounds), p);
  const tpc::SubdivisionResult& r = placed.Result;
  EXPECT_GT(r.FacingSurfaceCells, 0u);
  EXPECT_EQ(r.UnresolvedCells, r.FacingSurfaceCells);
  EXPECT_FALSE(r.DepthLimitReached);
  EXPECT_FALSE(r.CellLimitReached);
  EXPECT_EQ(placed.PlacementsTried, 1); // another lattice does not help
  const int toleranceLevel = tpc::ToleranceLevel(tpctest::GrownDomain(bounds), p.HausdorffTolerance);
  for (const tpc::OctreeNode& n : r.Octree.Nodes)
  {
    EXPECT_LE(n.Level, toleranceLevel);
    if (n.State == tpc::CellState::Unresolved)
    {
      EXPECT_EQ(n.Reason, tpc::SplitReason::SurfacesTooClose);
      EXPECT_NE(n.FailedTest, tpc::SplitReason::None);
      EXPECT_LE(placed.Grid.CellDiagonal(n.Level), p.HausdorffTolerance);
      const Box3 cell = placed.Grid.CellBox(n.Level, n.Ijk);
      EXPECT_TRUE(cell.lo[0] <= 1.0 && cell.hi[0] >= 1.0) << "a stopped cell is on the shared face";
    }
  }
  const tpc::ExtractionResult e = tpc::ExtractSurface(r.Octree, b.Scene);
  const tpc::TopologyReport t = tpc::ComputeTopologyReport(e.Mesh);
  EXPECT_TRUE(t.Closed);
  EXPECT_TRUE(t.Manifold);
  // Flagged, yet the union's topology - one box - with no piece invented in
  // the stopped cells.
  EXPECT_EQ(t.Components, 1);
  EXPECT_EQ(t.Genus, 0);
}

TEST(FacingSurfaces, SpheresTouchingAtAPointAreFlaggedWithoutExtraPieces)
{
  // Tangential contact at one point: flagged (never passes, paper 5.3.3),
  // said why, and still two spheres' worth of surface - the contact is
  // either kept apart or joined, never a bubble or a sliver.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union(
    { b.Sphere({ -0.5013, 0.0021, 0.0007 }, 0.5), b.Sphere({ 0.4987, 0.0021, 0.0007 }, 0.5) }));
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, { { -1.01, -0.51, -0.51 }, { 1.01, 0.51, 0.51 } }, 1.0 / 64);
  EXPECT_FALSE(r.Guaranteed);
  EXPECT_GT(r.Subdivision.FacingSurfaceCells, 0u);
  ASSERT_FALSE(r.Messages.empty());
  EXPECT_NE(r.Messages.front().Text.find("SURFACES_TOO_CLOSE"), std::string::npos) << r.Messages.front().Text;
  // Closer than the lattice's own finest cell they touch: no other lattice
  // placement is tried (it would triple the time for nothing).
  EXPECT_EQ(r.Messages.front().Text.find("lattice placements"), std::string::npos) << r.Messages.front().Text;
  EXPECT_TRUE(r.Report.Closed);
  EXPECT_TRUE(r.Report.Manifold);
  EXPECT_GE(r.Report.Components, 1);
  EXPECT_LE(r.Report.Components, 2);
  EXPECT_EQ(r.Report.Genus, 0);
}

TEST(FacingSurfaces, AGapFarBelowTheFinestCellIsSeparatedAtTheTolerancesSize)
{
  // Two boxes 1e-7 apart, far below the finest cell of MaximumDepth 16:
  // the two faces' loops are located down to the lattice and a plane in the
  // gap separates them (LoopsSeparated), so the cells pass at the
  // tolerance's size - neither stopped as too close nor refined to the gap.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Box({ 0, 0, 0 }, { 1, 1, 1 }), b.Box({ 1 + 1e-7, 0, 0 }, { 2, 1, 1 }) }));
  const Box3 bounds{ { 0, 0, 0 }, { 2, 1, 1 } };
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, bounds, 0.02);
  EXPECT_TRUE(r.Guaranteed);
  EXPECT_EQ(r.Subdivision.FacingSurfaceCells, 0u);
  EXPECT_EQ(r.Report.Components, 2);
  EXPECT_EQ(r.Report.Genus, 0);
  const int toleranceLevel = tpc::ToleranceLevel(tpctest::GrownDomain(bounds), r.Tolerance);
  for (const tpc::OctreeNode& n : r.Subdivision.Octree.Nodes)
  {
    EXPECT_LE(n.Level, toleranceLevel + 1);
  }
}

TEST(FacingSurfaces, AGapOfAFewFinestCellsIsStillResolved)
{
  // The rule only gives up below the finest cell MaximumDepth allows.
  SceneBuilder b;
  const Box3 bounds{ { 0, 0, 0 }, { 2.02, 1, 1 } };
  tpc::SubdivisionParameters p;
  p.HausdorffTolerance = 0.05 * bounds.Diagonal();
  const Box3 domain = tpctest::GrownDomain(bounds);
  p.MaximumDepth = tpc::ToleranceLevel(domain, p.HausdorffTolerance) + 3;
  const double finest = std::ldexp(tpc::MakeRootGrid(domain, p.HausdorffTolerance, p.MaximumDepth).RootSize,
    -p.MaximumDepth);
  const double gap = 3.0 * finest;
  b.Finish(SceneBuilder::Union({ b.Box({ 0, 0, 0 }, { 1, 1, 1 }), b.Box({ 1 + gap, 0, 0 }, { 2, 1, 1 }) }));
  const tpc::PlacedSubdivision placed = tpc::RunOnBestLatticePlacement(b.Scene, domain, p);
  EXPECT_EQ(placed.Result.UnresolvedCells, 0u);
  EXPECT_EQ(placed.Result.FacingSurfaceCells, 0u);
  const tpc::ExtractionResult e = tpc::ExtractSurface(placed.Result.Octree, b.Scene);
  const tpc::TopologyReport t = tpc::ComputeTopologyReport(e.Mesh);
  EXPECT_EQ(t.Components, 2);
  EXPECT_EQ(t.Genus, 0);
}
