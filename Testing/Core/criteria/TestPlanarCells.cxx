// Error-driven acceptance of plane sections (PlanarCell.h): which cells
// qualify, and that the surfaces they give keep the two-sided Hausdorff bound
// (measured) and the topology while being far coarser than the tolerance.
#include "CoreContour.h"
#include "MeshBuilders.h"
#include "PlanarCell.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using tpc::Box3;
using tpc::CsgExpression;
using tpc::Quadric;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
/// Whether the expression pruned to `cell` counts as plane sections there.
bool Planar(const tpc::ImplicitScene& scene, const Box3& cell)
{
  const auto pruned = CsgExpression::Prune(scene.Expression, cell, scene.Primitives);
  return pruned.Sign == tpc::RegionSign::Mixed && tpc::IsPlanarCell(*pruned.Expression, scene.Primitives, cell);
}

/// Exact distance from p to the boundary of the box [lo, hi].
double DistanceToBoxSurface(const Vec3& p, const Vec3& lo, const Vec3& hi)
{
  double outside = 0.0, inside = HUGE_VAL;
  for (int a = 0; a < 3; ++a)
  {
    const double d = std::max({ lo[a] - p[a], 0.0, p[a] - hi[a] });
    outside += d * d;
    inside = std::min({ inside, p[a] - lo[a], hi[a] - p[a] });
  }
  return outside > 0.0 ? std::sqrt(outside) : std::max(inside, 0.0);
}

/// The output as a mesh solid, to measure distances to it.
tpc::MeshSolid OutputSolid(const tpc::TriangleMesh& m)
{
  return tpc::MeshSolid(m.Points.ToVector(), m.Triangles.ToVector());
}

/// Surface leaves larger than the tolerance (kept as plane sections).
/// Surface leaves larger than the tolerance (`creaseFans`: only those that
/// are crease fans, QuadricCellError.h).
std::size_t OversizedSurfaceLeaves(const tpctest::ContourRun& r, bool creaseFans = false)
{
  std::size_t n = 0;
  for (const tpc::OctreeNode& node : r.Subdivision.Octree.Nodes)
  {
    n += node.IsLeaf() && node.State == tpc::CellState::Surface &&
        r.Subdivision.Octree.Grid.CellDiagonal(node.Level) > r.Tolerance && (!creaseFans || node.CreaseFan)
      ? 1
      : 0;
  }
  return n;
}
} // namespace

TEST(PlanarCells, WhichCellsAreDisjointPlaneSections)
{
  const Box3 cell{ { -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 } };
  {
    SceneBuilder b; // one plane
    b.Finish(b.Add(Quadric::Plane({ 0.1, 0, 0 }, { 1, 0.2, 0.3 })));
    EXPECT_TRUE(Planar(b.Scene, cell));
  }
  {
    SceneBuilder b; // a thin plate: both faces in the cell, parallel
    b.Finish(b.Box({ -2, -2, -0.05 }, { 2, 2, 0.05 }));
    EXPECT_TRUE(Planar(b.Scene, cell));
    EXPECT_FALSE(Planar(b.Scene, { { 1.5, -0.5, -0.5 }, { 2.5, 0.5, 0.5 } })); // an edge of the plate
  }
  {
    SceneBuilder b; // a wedge: two planes crossing at x = -2, inside one cell, outside another
    b.Finish(SceneBuilder::Intersection({ b.Add(Quadric::Plane({ 0, 0, 0.2 }, { -0.1, 0, 1 })),
      b.Add(Quadric::Plane({ 0, 0, -0.2 }, { -0.1, 0, -1 })) }));
    EXPECT_TRUE(Planar(b.Scene, cell));
    EXPECT_FALSE(Planar(b.Scene, { { -2.5, -0.5, -0.5 }, { -1.5, 0.5, 0.5 } }));
  }
  {
    SceneBuilder b; // curved
    b.Finish(b.Sphere({ 0, 0, 0 }, 0.3));
    EXPECT_FALSE(Planar(b.Scene, cell));
  }
  {
    SceneBuilder b; // a mesh: a cell on one face, and one on an edge
    b.Finish(b.Mesh(tpctest::CubeMesh({ -1, -1, -1 }, { 1, 1, 1 })));
    EXPECT_TRUE(Planar(b.Scene, { { -0.3, -0.3, 0.8 }, { 0.3, 0.3, 1.2 } }));
    EXPECT_FALSE(Planar(b.Scene, { { 0.8, -0.3, 0.8 }, { 1.2, 0.3, 1.2 } }));
  }
  {
    // A corner moved off the face's plane by one part in 1e13: the face's two
    // triangles are no longer coplanar (exact predicates, no tolerance).
    tpc::MeshSolid cube = tpctest::CubeMesh({ -1, -1, -1 }, { 1, 1, 1 });
    std::vector<Vec3> p = cube.Points();
    p[7][2] += 1e-13;
    SceneBuilder b;
    b.Finish(b.Mesh(tpc::MeshSolid(p, cube.Triangles())));
    EXPECT_FALSE(Planar(b.Scene, { { -1.2, -1.2, 0.8 }, { 1.2, 1.2, 1.2 } }));
    EXPECT_TRUE(Planar(b.Scene, { { -0.3, -0.3, -1.2 }, { 0.3, 0.3, -0.8 } }));
  }
}

TEST(PlanarCells, ThinPlateStaysCoarseWithinTheTwoSidedBound)
{
  // A 2 x 2 x 0.1 plate at a tolerance of 1 % of its diagonal: its faces are
  // covered by cells many times larger than the tolerance, and the measured
  // two-sided Hausdorff distance stays within it.
  const Vec3 lo{ -1, -1, -0.05 }, hi{ 1, 1, 0.05 };
  SceneBuilder b;
  b.Finish(b.Box(lo, hi));
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, { lo, hi }, 0.01);

  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_TRUE(r.Report.Closed);
  EXPECT_TRUE(r.Report.Manifold);
  EXPECT_EQ(r.Report.Components, 1);
  EXPECT_EQ(r.Report.Genus, 0);
  EXPECT_NEAR(r.Report.SignedVolume, 0.4, 1e-3); // (the rim's creases are cut)
  EXPECT_GT(r.Subdivision.PlanarSurfaceCells, 0u);
  // The rest of the large cells hold the rim's edges: two planes' creases,
  // each cell a fan around a point of its edge (QuadricCellError.h).
  EXPECT_GT(OversizedSurfaceLeaves(r, true), 0u);
  EXPECT_EQ(OversizedSurfaceLeaves(r), r.Subdivision.PlanarSurfaceCells + OversizedSurfaceLeaves(r, true));
  EXPECT_LE(r.Subdivision.HausdorffBound, r.Tolerance);

  // Exact where the cell is a plane section: every vertex of those cells'
  // triangles lies on the plate's surface (up to rounding).
  const auto& mesh = r.Extraction.Mesh;
  const tpc::AdaptiveOctree& tree = r.Subdivision.Octree;
  std::size_t coarseTriangles = 0;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const tpc::OctreeNode& node = tree.Nodes[mesh.TriangleCell[t]];
    const bool coarse = tree.Grid.CellDiagonal(node.Level) > r.Tolerance;
    coarseTriangles += coarse ? 1 : 0;
    for (const auto v : mesh.Triangles[t])
    {
      const double d = DistanceToBoxSurface(mesh.Points[v], lo, hi);
      ASSERT_LE(d, coarse ? 1e-12 : r.Tolerance);
    }
  }
  // Most of the plate's area is in coarse cells.
  EXPECT_GT(coarseTriangles, mesh.Triangles.size() / 4);

  // The other side: random points of the plate's surface are within the
  // tolerance of the output.
  const tpc::MeshSolid output = OutputSolid(mesh);
  tpc::TriangleList all(mesh.Triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t)
  {
    all[t] = static_cast<std::uint32_t>(t);
  }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int s = 0; s < 2000; ++s)
  {
    // Top and bottom faces, and the rim.
    Vec3 q(u(rng), u(rng), s % 2 ? hi[2] : lo[2]);
    if (s % 5 == 0)
    {
      q = Vec3(s % 10 ? hi[0] : lo[0], u(rng), 0.05 * u(rng));
    }
    worst = std::max(worst, std::fabs(output.ApproximateSignedDistance(q, all)));
  }
  EXPECT_LE(worst, r.Tolerance);
}

TEST(PlanarCells, FlatMeshFacesStayCoarseAndTopologyHolds)
{
  // A cube mesh minus a cylinder through it (genus 1): the cube's faces are
  // plane sections away from the hole and its edges.
  SceneBuilder b;
  b.Finish(SceneBuilder::Difference(
    { b.Mesh(tpctest::CubeMesh({ -1, -1, -1 }, { 1, 1, 1 })), b.Cylinder({ 0.11, 0.07, 0 }, { 0, 0, 1 }, 0.4) }));
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, { { -1, -1, -1 }, { 1, 1, 1 } }, 0.02);
  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_TRUE(r.Report.Closed);
  EXPECT_TRUE(r.Report.Manifold);
  EXPECT_EQ(r.Report.Components, 1);
  EXPECT_EQ(r.Report.Genus, 1);
  EXPECT_GT(r.Subdivision.PlanarSurfaceCells, 0u);
  // (The others on the cylinder, with their error certified: QuadricCellError.h.)
  EXPECT_EQ(OversizedSurfaceLeaves(r),
    r.Subdivision.PlanarSurfaceCells + r.Subdivision.OversizedErrorBoundedCells);
  EXPECT_LE(r.HausdorffBound, r.Tolerance);
  // Every output vertex is within the tolerance of the exact surface: on the
  // cube's faces, or on the cylinder inside the cube.
  for (const Vec3& p : r.Extraction.Mesh.Points)
  {
    const double toCube = DistanceToBoxSurface(p, { -1, -1, -1 }, { 1, 1, 1 });
    const double toCylinder = std::fabs(std::hypot(p[0] - 0.11, p[1] - 0.07) - 0.4);
    ASSERT_LE(std::min(toCube, toCylinder), r.Tolerance);
  }
}
