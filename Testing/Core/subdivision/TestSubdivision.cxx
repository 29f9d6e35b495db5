// The whole core pipeline (subdivision + extraction + report) on small
// scenes: adaptivity, the two-sided Hausdorff bound, closed manifold output,
// and what happens when a limit stops refinement.
#include "CoreContour.h"
#include "MeshBuilders.h"
#include "QuadricCellError.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using tpc::Box3;
using tpc::Vec3;
using tpctest::SceneBuilder;

using tpctest::Contour;
using tpctest::ContourRun;

namespace
{
/// The deepest level of a run's octree.
int DeepestLevel(const ContourRun& r)
{
  int deepest = 0;
  for (const tpc::OctreeNode& n : r.Subdivision.Octree.Nodes)
  {
    deepest = std::max(deepest, static_cast<int>(n.Level));
  }
  return deepest;
}
} // namespace

TEST(Subdivision, SphereIsAdaptiveClosedAndWithinTolerance)
{
  SceneBuilder b;
  const Vec3 c{ 0.1, 0.2, 0.3 };
  const double radius = 0.5;
  b.Finish(b.Sphere(c, radius));
  const Box3 bounds{ c - Vec3(radius, radius, radius), c + Vec3(radius, radius, radius) };
  const ContourRun r = Contour(b.Scene, bounds, 0.03);

  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_EQ(r.Extraction.InconsistentCells, 0u);
  EXPECT_TRUE(r.Report.Closed);
  EXPECT_TRUE(r.Report.Manifold);
  EXPECT_TRUE(r.Report.Oriented);
  EXPECT_EQ(r.Report.Components, 1);
  EXPECT_EQ(r.Report.Genus, 0);
  EXPECT_EQ(r.Report.EulerCharacteristic, 2);
  EXPECT_NEAR(r.Report.SignedVolume, 4.0 / 3.0 * M_PI * radius * radius * radius, 0.02);

  // Adaptive: far from the surface cells stay coarse, and the tree is a tiny
  // fraction of a uniform grid at the finest level.
  int deepest = 0;
  bool coarseEmptyLeaf = false;
  for (const tpc::OctreeNode& n : r.Subdivision.Octree.Nodes)
  {
    deepest = std::max(deepest, static_cast<int>(n.Level));
    coarseEmptyLeaf |= n.IsLeaf() && n.Level <= 3 &&
      (n.State == tpc::CellState::Inside || n.State == tpc::CellState::Outside);
  }
  EXPECT_TRUE(coarseEmptyLeaf);
  EXPECT_LT(static_cast<double>(r.Subdivision.Octree.Nodes.size()), 0.1 * std::pow(8.0, deepest));

  // A smooth surface: loops are triangulated from their own points as
  // Marching Cubes does (k - 2 triangles for a loop of k crossings), not as
  // fans around a centre (k triangles): 2.0 triangles per cell here, 3.5 with
  // centres.
  EXPECT_LT(r.Extraction.Mesh.Triangles.size(), 3 * r.Subdivision.SurfaceCells);

  // Two-sided Hausdorff distance <= the proven bound <= tolerance: every
  // vertex is within it of the sphere (cells larger than the tolerance keep
  // their error certified, QuadricCellError.h), and every sampled sphere
  // point is within it of the output's triangles.
  ASSERT_LE(r.HausdorffBound, r.Tolerance * (1 + 1e-9));
  const auto& mesh = r.Extraction.Mesh;
  for (const Vec3& p : mesh.Points)
  {
    ASSERT_LE(std::fabs(tpc::Norm(p - c) - radius), r.HausdorffBound);
  }
  const tpc::MeshSolid output(mesh.Points.ToVector(), mesh.Triangles.ToVector());
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g;
  for (int s = 0; s < 300; ++s)
  {
    const Vec3 q = c + tpc::Normalized(Vec3(g(rng), g(rng), g(rng))) * radius;
    const Box3 near{ q - Vec3(r.Tolerance, r.Tolerance, r.Tolerance), q + Vec3(r.Tolerance, r.Tolerance, r.Tolerance) };
    const tpc::TriangleList candidates = output.Overlapping(near);
    ASSERT_FALSE(candidates.empty());
    ASSERT_LE(std::fabs(output.ApproximateSignedDistance(q, candidates)), r.HausdorffBound);
  }
}

TEST(Subdivision, BoxMinusCylinderHasGenusOne)
{
  SceneBuilder b;
  b.Finish(SceneBuilder::Difference({ b.Box({ -0.5, -0.5, -0.3 }, { 0.5, 0.5, 0.3 }),
    b.Cylinder({ 0.05, 0.02, 0 }, { 0, 0, 1 }, 0.2) }));
  const ContourRun r = Contour(b.Scene, { { -0.5, -0.5, -0.3 }, { 0.5, 0.5, 0.3 } }, 0.05);
  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_TRUE(r.Report.Manifold);
  EXPECT_EQ(r.Report.Components, 1);
  EXPECT_EQ(r.Report.Genus, 1);
  EXPECT_GT(r.Report.SignedVolume, 0.0);
}

TEST(Subdivision, DepthLimitMarksCellsAndStillGivesAClosedManifold)
{
  // Two spheres 0.2 % of the diagonal apart need deep cells to separate; a
  // depth limit of 4 stops well before.
  SceneBuilder b;
  const double gap = 0.002 * std::sqrt(3.0) * 2.0;
  b.Finish(SceneBuilder::Union({ b.Sphere({ -0.5 - gap / 2, 0, 0 }, 0.5), b.Sphere({ 0.5 + gap / 2, 0, 0 }, 0.5) }));
  const Box3 bounds{ { -1 - gap / 2, -0.5, -0.5 }, { 1 + gap / 2, 0.5, 0.5 } };
  const ContourRun limited = Contour(b.Scene, bounds, 0.05, 4);
  EXPECT_GT(limited.Subdivision.UnresolvedCells, 0u);
  EXPECT_TRUE(limited.Subdivision.DepthLimitReached);
  EXPECT_TRUE(limited.Report.Closed);
  EXPECT_TRUE(limited.Report.Manifold);
  std::size_t marked = 0;
  for (const tpc::OctreeNode& n : limited.Subdivision.Octree.Nodes)
  {
    if (n.State == tpc::CellState::Unresolved)
    {
      EXPECT_EQ(n.Reason, tpc::SplitReason::LimitReached);
      EXPECT_NE(n.FailedTest, tpc::SplitReason::None);
      ++marked;
    }
  }
  EXPECT_EQ(marked, limited.Subdivision.UnresolvedCells);

  const ContourRun full = Contour(b.Scene, bounds, 0.05);
  EXPECT_EQ(full.Subdivision.UnresolvedCells, 0u);
  EXPECT_EQ(full.Report.Components, 2);
}

TEST(Subdivision, TangentialContactEndsAtTheLimitWithoutAGuarantee)
{
  // Paper 5.3.3: tangential contact never passes the tests.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Sphere({ -0.5, 0, 0 }, 0.5), b.Sphere({ 0.5, 0, 0 }, 0.5) }));
  const ContourRun r = Contour(b.Scene, { { -1, -0.5, -0.5 }, { 1, 0.5, 0.5 } }, 0.05, 9);
  EXPECT_GT(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_TRUE(r.Report.Closed);
  EXPECT_TRUE(r.Report.Manifold);
}

TEST(Subdivision, NearContactsSeparateWithoutRefiningToTheGap)
{
  // Two spheres of radius 0.5 whose gap is 1e-3, 1e-6, 1e-9 of a domain 2
  // wide, at the default MaximumDepth. The loops on either side of the gap are
  // located down to the lattice and separated by a plane in the gap that
  // the surface provably misses (LoopsSeparated); each cap passes the
  // star-shaped test on its own side. So the cells at the contact pass at
  // the tolerance's size: two components, guaranteed, no cell stopped as
  // "surfaces too close", nothing refined towards the gap.
  for (const double gap : { 1e-3, 1e-6, 1e-9 })
  {
    SceneBuilder b;
    b.Finish(SceneBuilder::Union({ b.Sphere({ -0.5013, 0.0021, 0.0007 }, 0.5),
      b.Sphere({ 0.4987 + 2 * gap, 0.0021, 0.0007 }, 0.5) }));
    const Box3 bounds{ { -1.01, -0.51, -0.51 }, { 1.01, 0.51, 0.51 } };
    for (const double tolerance : { 1.0 / 32, 1.0 / 64 })
    {
      const ContourRun r = Contour(b.Scene, bounds, tolerance);
      EXPECT_TRUE(r.Guaranteed) << gap << " " << tolerance;
      EXPECT_EQ(r.Subdivision.FacingSurfaceCells, 0u) << gap;
      EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u) << gap;
      EXPECT_EQ(r.Report.Components, 2) << gap;
      EXPECT_EQ(r.Report.Genus, 0) << gap;
      EXPECT_TRUE(r.Report.Closed && r.Report.Manifold) << gap;
      EXPECT_LE(DeepestLevel(r), 12) << gap << ": refined towards the gap";
    }
  }
}

TEST(Subdivision, ThinWedgesInAnyOrientationResolve)
{
  // A box cut by two planes meeting at 30, 10 and 3 degrees along a line
  // tilted to every axis: the solid is a thin wedge. Its edge's cells
  // resolve a few levels below the tolerance's size: the tiles it pierces
  // are split inside the wedge (FaceRefinement.h), the two sheets beside it
  // are separated by an oblique plane (LoopsSeparated) - before, they failed
  // at every level until stopped as too close. At 3 degrees two cells
  // needed more than MaximumDepth 16 on this lattice; the default (the
  // lattice's end) resolves them.
  for (const double degrees : { 30.0, 10.0, 3.0 })
  {
    SceneBuilder b;
    const Vec3 o{ 0.1234, 0.0567, 0.0891 };
    const Vec3 t = tpc::Normalized(Vec3{ 0.31, 0.93, 0.17 });
    const Vec3 n1 = tpc::Normalized(tpc::Cross(t, Vec3{ 1, 0, 0.3 }));
    const Vec3 m = tpc::Cross(t, n1);
    const double a = degrees * M_PI / 180.0;
    const Vec3 n2 = (n1 * std::cos(a) + m * std::sin(a)) * -1.0;
    b.Finish(SceneBuilder::Intersection({ b.Box({ -1, -1, -1 }, { 1, 1, 0.3 }), b.Add(tpc::Quadric::Plane(o, n1)),
      b.Add(tpc::Quadric::Plane(o, n2)) }));
    const ContourRun r = Contour(b.Scene, { { -1.0371, -1.0213, -1.0517 }, { 1.0423, 1.0312, 0.3317 } }, 0.01);
    EXPECT_TRUE(r.Guaranteed) << degrees;
    EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u) << degrees;
    EXPECT_EQ(r.Report.Components, 1) << degrees;
    EXPECT_EQ(r.Report.Genus, 0) << degrees;
    EXPECT_TRUE(r.Report.Closed && r.Report.Manifold) << degrees;
  }
}

TEST(Subdivision, SmallComponentResolvesBelowTheOldLatticesEnd)
{
  // A bubble of radius 1e-7 beside a sphere, in a domain 2 wide: its cells
  // must reach level 22 or so before a corner falls inside it. At
  // MaximumDepth 16 the cells around it are stopped at the limit, the
  // guarantee withdrawn. At the default (the lattice's end, 42 bits,
  // RootGrid.h) refinement goes below level 19, where the old 20-bit lattice
  // ended, only around the bubble: two components, guaranteed.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union(
    { b.Sphere({ -0.5013, 0.0021, 0.0007 }, 0.5), b.Sphere({ 0.7071, 0.0123, -0.0031 }, 1e-7) }));
  const Box3 bounds{ { -1.01, -0.51, -0.51 }, { 1.01, 0.51, 0.51 } };
  const ContourRun stopped = Contour(b.Scene, bounds, 1.0 / 32, 16, 1);
  EXPECT_TRUE(stopped.Subdivision.DepthLimitReached);
  EXPECT_FALSE(stopped.Guaranteed);
  const ContourRun resolved = Contour(b.Scene, bounds, 1.0 / 32, tpc::DeepestMaximumDepth, 1);
  EXPECT_EQ(resolved.Subdivision.UnresolvedCells, 0u);
  EXPECT_TRUE(resolved.Guaranteed);
  EXPECT_EQ(resolved.Report.Components, 2);
  EXPECT_EQ(resolved.Report.Genus, 0);
  EXPECT_GT(DeepestLevel(resolved), 19);
}

TEST(Subdivision, SharpWedgesResolveAtADepthGrowingWithTheAngle)
{
  // A box cut at 30, 10, 3 and 1 degrees to its top face: a wedge along a
  // line. The cells at its edge resolve a bounded number of levels below
  // the tolerance's, growing with log2(1/angle), not at the lattice's end
  // (issue 16). Measured deepest levels (tolerance level 8, one lattice
  // placement): 12, 12, 13, 16, 17, 19, 19, 16 at 30, 10, 3, 2, 1.5, 1, 0.5,
  // 0.25 degrees - where the edge falls on the lattice matters as much as
  // the angle. The 1-degree wedge needs levels beyond 16, where the old
  // default MaximumDepth stopped 28 cells; the default, the lattice's end,
  // costs nothing where it is not needed.
  for (const double degrees : { 30.0, 10.0, 3.0, 1.0 })
  {
    const double a = degrees * M_PI / 180.0;
    SceneBuilder b;
    b.Finish(SceneBuilder::Intersection({ b.Box({ -1, -1, -1 }, { 1, 1, 0.3 }),
      b.Add(tpc::Quadric::Plane({ 0.1234, 0, 0.3 }, { -std::sin(a), -0.0123, -std::cos(a) })) }));
    const Box3 bounds{ { -1.0371, -1.0213, -1.0517 }, { 1.0423, 1.0312, 0.3317 } };
    const ContourRun r = Contour(b.Scene, bounds, 0.01, tpc::DeepestMaximumDepth, 1);
    EXPECT_TRUE(r.Guaranteed) << degrees;
    EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u) << degrees;
    EXPECT_EQ(r.Report.Components, 1) << degrees;
    EXPECT_EQ(r.Report.Genus, 0) << degrees;
    const int toleranceLevel = tpc::ToleranceLevel(tpctest::GrownDomain(bounds), r.Tolerance);
    const int logAngle = static_cast<int>(std::ceil(std::log2(30.0 / degrees)));
    EXPECT_LE(DeepestLevel(r), toleranceLevel + 4 + 2 * logAngle) << degrees;
    if (degrees == 1.0)
    {
      EXPECT_GT(DeepestLevel(r), 16);
      const ContourRun old = Contour(b.Scene, bounds, 0.01, 16, 1);
      EXPECT_FALSE(old.Guaranteed);
      EXPECT_GT(old.Subdivision.UnresolvedCells, 0u);
    }
  }
}

TEST(Subdivision, SpheresOverlappingByAHairFormOneSolid)
{
  // Two spheres of radius 0.5 overlapping by 1e-6 of the domain: the exact
  // union is one component joined by a neck 1e-3 wide, with a sharp
  // exterior wedge around it. Resolved at the default MaximumDepth (at 16
  // the neck's cells were stopped and the output had two components).
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Sphere({ -0.5013, 0.0021, 0.0007 }, 0.5),
    b.Sphere({ 0.4987 - 2e-6, 0.0021, 0.0007 }, 0.5) }));
  const Box3 bounds{ { -1.01, -0.51, -0.51 }, { 1.01, 0.51, 0.51 } };
  const ContourRun r = Contour(b.Scene, bounds, 1.0 / 64);
  EXPECT_TRUE(r.Guaranteed);
  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_EQ(r.Report.Components, 1);
  EXPECT_EQ(r.Report.Genus, 0);
  EXPECT_TRUE(r.Report.Closed && r.Report.Manifold);
  const ContourRun old = Contour(b.Scene, bounds, 1.0 / 64, 16);
  EXPECT_FALSE(old.Guaranteed);
}

namespace
{
/// `near` says what `scene` says at random points of leaf n's cell grown by
/// the tolerance.
void ExpectSameOnGrownCell(const tpc::AdaptiveOctree& tree, std::uint32_t n, const tpc::CsgExpression& near,
  const tpc::CsgExpression& scene, const tpc::PrimitiveSet& primitives, std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const tpc::OctreeNode& node = tree.Nodes[n];
  const Box3 grown = tpc::GrownByMargin(tree.Grid.CellBox(node.Level, node.Ijk), tree.HausdorffTolerance);
  for (int s = 0; s < 40; ++s)
  {
    Vec3 p;
    for (int a = 0; a < 3; ++a)
    {
      p[a] = grown.lo[a] + u(rng) * (grown.hi[a] - grown.lo[a]);
    }
    ASSERT_EQ(near.IsInside(p, primitives), scene.IsInside(p, primitives))
      << "leaf " << n << " at " << p[0] << " " << p[1] << " " << p[2];
  }
}
} // namespace

TEST(Subdivision, NearExpressionsAreTheScenesOnEveryGrownCell)
{
  // A plate with a row of holes: many primitives, few near any one cell.
  // Each surface leaf keeps the scene's expression pruned to its cell grown
  // by the tolerance, pruned from its parent's (QuadricCellError.h looks
  // there): it must say what the whole scene says everywhere in that box.
  SceneBuilder b;
  std::vector<tpc::CsgTerm> holes;
  for (int i = 0; i < 9; ++i)
  {
    holes.push_back(b.Sphere({ -0.6 + 0.15 * i, 0.03 * (i % 3), 0.0 }, 0.06 + 0.001 * i));
  }
  std::vector<tpc::CsgTerm> parts{ b.Box({ -0.7, -0.2, -0.05 }, { 0.7, 0.2, 0.05 }) };
  parts.insert(parts.end(), holes.begin(), holes.end());
  b.Finish(SceneBuilder::Difference(parts));
  const ContourRun r = Contour(b.Scene, { { -0.7, -0.2, -0.05 }, { 0.7, 0.2, 0.05 } }, 1.0 / 64);
  EXPECT_TRUE(r.Guaranteed);
  EXPECT_EQ(r.Report.Genus, 9);
  const tpc::AdaptiveOctree& tree = r.Subdivision.Octree;
  ASSERT_EQ(tree.NearExpressions.size(), tree.Nodes.size());
  const std::size_t sceneLeaves = b.Scene.Expression->Leaves().size();
  std::mt19937_64 rng(5);
  std::size_t checked = 0, largest = 0;
  for (std::uint32_t n = 0; n < tree.Nodes.size(); ++n)
  {
    const tpc::OctreeNode& node = tree.Nodes[n];
    if (!node.IsLeaf() || node.State != tpc::CellState::Surface)
    {
      continue;
    }
    ASSERT_TRUE(tree.NearExpressions[n]) << "surface leaf " << n;
    const tpc::CsgExpression& near = *tree.NearExpressions[n];
    largest = std::max(largest, near.Leaves().size());
    ExpectSameOnGrownCell(tree, n, near, *b.Scene.Expression, b.Scene.Primitives, rng);
    ++checked;
  }
  EXPECT_GT(checked, 100u);
  // Not the scene again (six planes and nine spheres): a grown cell meets a
  // few planes of the plate and a hole.
  EXPECT_EQ(sceneLeaves, 15u);
  EXPECT_LE(largest, 5u);
}

TEST(Subdivision, NearExpressionsWhereACellHoldsNoMesh)
{
  // A cube mesh minus eight spheres inside it: cells of a sphere alone keep
  // the scene pruned to their grown cell (the quadric bound looks there, not
  // at the whole scene with its mesh), cells holding the mesh none.
  SceneBuilder b;
  std::vector<tpc::CsgTerm> parts{ b.Mesh(tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 })) };
  for (int k = 0; k < 8; ++k)
  {
    parts.push_back(b.Sphere({ k & 1 ? 0.21 : -0.2, k & 2 ? 0.22 : -0.19, k & 4 ? 0.2 : -0.23 }, 0.12));
  }
  b.Finish(SceneBuilder::Difference(parts));
  const ContourRun r = Contour(b.Scene, { { -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 } }, 1.0 / 64);
  EXPECT_TRUE(r.Guaranteed);
  EXPECT_EQ(r.Report.Components, 9);
  const tpc::AdaptiveOctree& tree = r.Subdivision.Octree;
  ASSERT_EQ(tree.NearExpressions.size(), tree.Nodes.size());
  std::mt19937_64 rng(9);
  std::size_t withMesh = 0, without = 0, largest = 0;
  for (std::uint32_t n = 0; n < tree.Nodes.size(); ++n)
  {
    const tpc::OctreeNode& node = tree.Nodes[n];
    if (!node.IsLeaf() || node.State != tpc::CellState::Surface)
    {
      continue;
    }
    if (tree.Expressions[n]->HasMeshLeaves())
    {
      ++withMesh;
      EXPECT_FALSE(tree.NearExpressions[n]) << "leaf " << n;
      EXPECT_EQ(tree.NearExpression(n, r.Tolerance), tree.SceneExpression);
      continue;
    }
    ++without;
    ASSERT_TRUE(tree.NearExpressions[n]) << "leaf " << n;
    const tpc::CsgExpression& near = *tree.NearExpressions[n];
    largest = std::max(largest, near.Leaves().size());
    ExpectSameOnGrownCell(tree, n, near, *b.Scene.Expression, b.Scene.Primitives, rng);
  }
  EXPECT_GT(withMesh, 20u);
  EXPECT_GT(without, 100u);
  // Not the scene again (the mesh and eight spheres): one sphere.
  EXPECT_EQ(b.Scene.Expression->Leaves().size(), 9u);
  EXPECT_EQ(largest, 1u);
}

TEST(Subdivision, LatticePlacementsDifferAndAllCoverTheDomain)
{
  const Box3 domain{ Vec3(-0.3, 0.1, -1.0), Vec3(0.9, 0.4, 1.0) };
  std::vector<Vec3> origins;
  for (int placement = 0; placement < tpc::LatticePlacements; ++placement)
  {
    const tpc::RootGrid g = tpc::MakeRootGrid(domain, 0.01, 16, placement);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_LE(g.Origin[a], domain.lo[a]);
      EXPECT_GE(g.Origin[a] + g.Dims[a] * g.RootSize, domain.hi[a]);
    }
    for (const Vec3& o : origins)
    {
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_NE(o[a], g.Origin[a]) << "placement " << placement << " axis " << a;
      }
    }
    origins.push_back(g.Origin);
  }
}

TEST(Subdivision, ProgressRisesMonotonicallyOverLatticePlacementRetries)
{
  // A depth limit above the tolerance's level leaves cells unresolved on
  // every placement: all are tried.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ b.Sphere({ -0.5, 0, 0 }, 0.5), b.Sphere({ 0.5, 0, 0 }, 0.5) }));
  tpc::SubdivisionParameters params;
  params.HausdorffTolerance = 0.1;
  params.MaximumDepth = 4;
  std::vector<double> reported;
  const tpc::PlacedSubdivision placed = tpc::RunOnBestLatticePlacement(b.Scene,
    { { -1, -0.5, -0.5 }, { 1, 0.5, 0.5 } }, params, tpc::LatticePlacements, tpc::SequentialFor,
    [&reported](double f) {
      reported.push_back(f);
      return false;
    });
  EXPECT_EQ(placed.PlacementsTried, tpc::LatticePlacements);
  ASSERT_FALSE(reported.empty());
  for (std::size_t i = 1; i < reported.size(); ++i)
  {
    ASSERT_GE(reported[i], reported[i - 1]) << "progress went back at report " << i;
  }
  EXPECT_GE(reported.front(), 0.0);
  EXPECT_DOUBLE_EQ(reported.back(), 1.0);
}

TEST(Subdivision, CellsNamedToSplitFirstSplitBeforeTheirTests)
{
  // A sphere whose cells pass larger than the tolerance (QuadricCellError.h).
  // Named as an earlier surface names the cells it found wanting
  // (CellRepair.h), three of them split with the reason given, before any
  // test; their children are tested as usual.
  SceneBuilder b;
  b.Finish(b.Sphere({ 0.02, -0.03, 0.01 }, 0.8));
  const tpc::RootGrid grid = tpctest::SingleRoot({ -1.03, -1.01, -1.02 }, 2.1, 16);
  tpc::SubdivisionParameters p;
  p.HausdorffTolerance = 0.02;
  p.MaximumDepth = 16;
  const tpc::SubdivisionResult first = tpc::RunTopologyPreservingSubdivision(b.Scene, grid, p);
  std::vector<std::uint32_t> named;
  for (std::uint32_t n = 0; n < first.Octree.Nodes.size() && named.size() < 3; ++n)
  {
    const tpc::OctreeNode& cell = first.Octree.Nodes[n];
    if (cell.IsLeaf() && cell.State == tpc::CellState::Surface && grid.CellDiagonal(cell.Level) > p.HausdorffTolerance)
    {
      named.push_back(n);
      const tpc::SplitReason reason =
        named.size() == 3 ? tpc::SplitReason::PatchNotEmbedded : tpc::SplitReason::PatchNotCertified;
      p.SplitFirst.Add({ cell.Level, { cell.Ijk[0], cell.Ijk[1], cell.Ijk[2] }, reason });
      // (A cell named twice keeps its first reason.)
      p.SplitFirst.Add({ cell.Level, { cell.Ijk[0], cell.Ijk[1], cell.Ijk[2] }, tpc::SplitReason::ComplexEdge });
    }
  }
  ASSERT_EQ(named.size(), 3u);
  ASSERT_EQ(p.SplitFirst.Size(), 3u);
  const tpc::SubdivisionResult again = tpc::RunTopologyPreservingSubdivision(b.Scene, grid, p);
  for (std::size_t k = 0; k < named.size(); ++k)
  {
    const tpc::OctreeNode& cell = first.Octree.Nodes[named[k]];
    const std::int64_t ijk[3] = { static_cast<std::int64_t>(cell.Ijk[0]), static_cast<std::int64_t>(cell.Ijk[1]),
      static_cast<std::int64_t>(cell.Ijk[2]) };
    const std::int64_t n = again.Octree.Find(cell.Level, ijk);
    ASSERT_GE(n, 0);
    const tpc::OctreeNode& split = again.Octree.Nodes[static_cast<std::size_t>(n)];
    EXPECT_EQ(split.Level, cell.Level);
    EXPECT_EQ(split.State, tpc::CellState::Refined);
    EXPECT_EQ(split.Reason, k == 2 ? tpc::SplitReason::PatchNotEmbedded : tpc::SplitReason::PatchNotCertified);
  }
  EXPECT_EQ(again.SplitsByReason[static_cast<int>(tpc::SplitReason::PatchNotCertified)], 2u);
  EXPECT_EQ(again.SplitsByReason[static_cast<int>(tpc::SplitReason::PatchNotEmbedded)], 1u);
  EXPECT_EQ(first.SplitsByReason[static_cast<int>(tpc::SplitReason::PatchNotCertified)], 0u);
  EXPECT_GT(again.Octree.Nodes.size(), first.Octree.Nodes.size());
  EXPECT_EQ(again.UnresolvedCells, 0u);
  // The surface over the new cells is closed and certified like any other.
  const tpc::ExtractionResult surface = tpc::ExtractSurface(again.Octree, b.Scene);
  EXPECT_EQ(surface.InconsistentCells, 0u);
  EXPECT_EQ(surface.UncertifiedCells, 0u);
  EXPECT_LE(surface.CertifiedBound, p.HausdorffTolerance);
  // Nothing named, nothing found.
  const tpc::LatticeIndex nowhere[3] = { 1, 2, 3 };
  EXPECT_EQ(p.SplitFirst.Find(1, nowhere), nullptr);
}
