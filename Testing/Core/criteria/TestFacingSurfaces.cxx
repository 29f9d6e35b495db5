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
