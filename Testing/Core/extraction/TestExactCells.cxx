// Exact cells (ExactCell.h) and the mesh/lattice arrangement they rest on
// (MeshArrangement.h): the exact side tests agree with MeshSolid's crossing
// counts (an independent implementation of the same perturbed solid), also
// on the degenerate cases the perturbation decides; clipped pieces of a
// triangle tile it; and whole runs whose cells keep the mesh are closed,
// manifold, embedded and of the exact topology, even with the mesh's
// vertices, edges and faces on lattice planes.
#include "CoreContour.h"
#include "ExactCell.h"
#include "ExactPredicates.h"
#include "MeshArrangement.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"

#include "TriangleErrorBounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

using tpc::ArrangementPoint;
using tpc::Vec3;

namespace
{
/// A lattice of spacing 1/4 from the origin: RootSize 4, MaxDepth 4.
tpc::RootGrid QuarterLattice()
{
  return tpctest::SingleRoot({ 0, 0, 0 }, 4.0, 4);
}

/// Random triangles with vertices on a grid of spacing 1/8 in [0, 4]^3: their
/// vertices, edges and faces hit lattice planes, lines and points often.
tpc::MeshSolid RandomTriangles(std::mt19937& rng, int count)
{
  std::uniform_int_distribution<int> c(0, 32);
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  while (static_cast<int>(triangles.size()) < count)
  {
    Vec3 p[3];
    for (Vec3& q : p)
    {
      q = { c(rng) / 8.0, c(rng) / 8.0, c(rng) / 8.0 };
    }
    if (tpc::Norm(tpc::Cross(p[1] - p[0], p[2] - p[0])) == 0.0)
    {
      continue;
    }
    const auto base = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), p, p + 3);
    triangles.push_back({ base, base + 1, base + 2 });
  }
  return tpc::MeshSolid(points, triangles);
}
} // namespace

TEST(MeshArrangement, TriangleOnALineAgreesWithMeshSolidCrossings)
{
  // Where triangle t meets a lattice line, the side tests against lattice
  // points s0 < s1 of the line say whether t crosses the segment [s0, s1]
  // exactly when MeshSolid's crossing count (its own perturbed predicates)
  // says so - ties included: many lines pass through edges and vertices.
  std::mt19937 rng(11);
  const tpc::RootGrid grid = QuarterLattice();
  const tpc::MeshSolid mesh = RandomTriangles(rng, 300);
  const tpc::MeshArrangement arrangement(mesh, grid);
  std::uniform_int_distribution<tpc::LatticeIndex> lattice(0, 16);
  int crossings = 0, ties = 0;
  for (std::uint32_t t = 0; t < mesh.TriangleCount(); ++t)
  {
    for (int trial = 0; trial < 100; ++trial)
    {
      const int axis = trial % 3, u = (axis + 1) % 3, v = (axis + 2) % 3;
      // Lines through the triangle's box, a third of them through a vertex
      // or an edge's midpoint where those lie on lattice lines.
      tpc::LatticeIndex lo[3], hi[3];
      const Vec3& corner = mesh.Vertex(t, trial % 3);
      const Vec3 middle = (mesh.Vertex(t, trial % 3) + mesh.Vertex(t, (trial + 1) % 3)) * 0.5;
      const Vec3& aim = trial % 6 < 3 ? corner : middle;
      for (const int k : { u, v })
      {
        const double l = aim[k] * 4.0;
        lo[k] = trial % 9 < 3 && l == std::floor(l) ? static_cast<tpc::LatticeIndex>(l) : lattice(rng);
        hi[k] = lo[k];
      }
      lo[axis] = lattice(rng) % 12;
      hi[axis] = lo[axis] + 1 + lattice(rng) % 4;
      const tpc::TriangleList only = { t };
      const int count = mesh.CountCrossings(grid.Point(lo), grid.Point(hi), axis, only);
      if (tpc::Orient2D(mesh.Vertex(t, 0)[u], mesh.Vertex(t, 0)[v], mesh.Vertex(t, 1)[u], mesh.Vertex(t, 1)[v],
            mesh.Vertex(t, 2)[u], mesh.Vertex(t, 2)[v]) == 0)
      {
        continue; // parallel to the line: never crossed
      }
      const ArrangementPoint y = ArrangementPoint::TriangleOnLine(t, axis, lo);
      // Only where the line meets the (perturbed) triangle: once below lo,
      // inside [lo, hi] or above hi - MeshSolid counts the middle case.
      const tpc::TriangleList none;
      const tpc::LatticeIndex far[2] = { 0u, 16u };
      tpc::LatticeIndex a[3] = { lo[0], lo[1], lo[2] }, b[3] = { lo[0], lo[1], lo[2] };
      a[axis] = far[0];
      b[axis] = far[1];
      if (mesh.CountCrossings(grid.Point(a), grid.Point(b), axis, only) == 0)
      {
        continue;
      }
      EXPECT_EQ(arrangement.Side(y, axis, lo[axis]) > 0 && arrangement.Side(y, axis, hi[axis]) < 0, count == 1)
        << "triangle " << t << " axis " << axis;
      const double at = arrangement.Position(y)[axis];
      ties += at == grid.Coordinate(axis, lo[axis]) || at == grid.Coordinate(axis, hi[axis]) ? 1 : 0;
      ++crossings;
    }
  }
  EXPECT_GT(crossings, 2000);
  EXPECT_GT(ties, 15); // the perturbation decided some
}

TEST(MeshArrangement, PlacedAsDecidedMeansOnTheDecidedSideOfEveryPlane)
{
  // An edge's crossing of a lattice plane, as computed, may sit on or past a
  // lattice plane that its exact side test puts it before (on a lattice line
  // exactly, the perturbation decides; rounding does the rest). Where
  // PlacedAsDecided accepts it, it is strictly on the decided side of every
  // lattice plane, so "inside a tile" means the same for the position and
  // the exact tests, for a tile and its sub-tiles (CreaseCrossing.h).
  std::mt19937 rng(5);
  const tpc::RootGrid grid = QuarterLattice();
  const tpc::MeshSolid mesh = RandomTriangles(rng, 300);
  const tpc::MeshArrangement arrangement(mesh, grid);
  int crossings = 0, accepted = 0, misplaced = 0;
  for (std::uint32_t t = 0; t < mesh.TriangleCount(); ++t)
  {
    const auto& ids = mesh.Triangles()[t];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = ids[k], b = ids[(k + 1) % 3];
      for (int axis = 0; axis < 3; ++axis)
      {
        for (tpc::LatticeIndex plane = 0; plane <= 16; ++plane)
        {
          if (arrangement.Side(ArrangementPoint::Vertex(a), axis, plane) ==
            arrangement.Side(ArrangementPoint::Vertex(b), axis, plane))
          {
            continue;
          }
          const ArrangementPoint x = ArrangementPoint::EdgeOnPlane(a, b, axis, plane);
          const Vec3 position = arrangement.Position(x);
          bool everyPlane = true;
          for (const int u : { (axis + 1) % 3, (axis + 2) % 3 })
          {
            for (tpc::LatticeIndex line = 0; line <= 16; ++line)
            {
              const double c = grid.Coordinate(u, line);
              everyPlane = everyPlane && (arrangement.Side(x, u, line) > 0 ? position[u] > c : position[u] < c);
            }
          }
          const bool placed = arrangement.PlacedAsDecided(x, position);
          EXPECT_TRUE(!placed || everyPlane) << "edge " << a << "-" << b << " on plane " << axis << "=" << plane;
          ++crossings;
          accepted += placed ? 1 : 0;
          misplaced += everyPlane ? 0 : 1;
        }
      }
    }
  }
  EXPECT_GT(crossings, 1000);
  EXPECT_GT(misplaced, 50); // on lattice lines: the perturbation decided, the position sits on the line
  EXPECT_GT(accepted, crossings / 2);
  std::cout << crossings << " crossings, " << misplaced << " not on the decided side of every plane, " << accepted
            << " accepted\n";
}

TEST(MeshArrangement, ClippedPiecesTileTheTriangle)
{
  // Each triangle clipped to the 64 boxes of a 4 x 4 x 4 block of lattice
  // cells: the pieces' areas add up to the triangle's (no gap, no overlap,
  // whatever the perturbation decided on the boxes' shared planes), and every
  // piece's vertices lie in its box.
  std::mt19937 rng(5);
  const tpc::RootGrid grid = QuarterLattice();
  const tpc::MeshSolid mesh = RandomTriangles(rng, 200);
  const tpc::MeshArrangement arrangement(mesh, grid);
  for (std::uint32_t t = 0; t < mesh.TriangleCount(); ++t)
  {
    double pieces = 0.0;
    for (std::uint32_t cell = 0; cell < 64; ++cell)
    {
      const tpc::LatticeIndex lo[3] = { 4 * (cell % 4), 4 * ((cell / 4) % 4), 4 * (cell / 16) };
      const tpc::LatticeIndex hi[3] = { lo[0] + 4, lo[1] + 4, lo[2] + 4 };
      const std::vector<tpc::ClippedVertex> polygon = arrangement.ClipTriangle(t, lo, hi);
      tpc::Box3 box{ grid.Point(lo), grid.Point(hi) };
      Vec3 area;
      for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        const Vec3 p = arrangement.Position(polygon[i].Point);
        const Vec3 q = arrangement.Position(polygon[(i + 1) % polygon.size()].Point);
        EXPECT_TRUE(box.Contains(p));
        area += tpc::Cross(p, q);
      }
      pieces += 0.5 * tpc::Norm(area);
    }
    const double whole = 0.5 * tpc::Norm(tpc::Cross(mesh.Vertex(t, 1) - mesh.Vertex(t, 0), mesh.Vertex(t, 2) - mesh.Vertex(t, 0)));
    EXPECT_NEAR(pieces, whole, 1e-9 * (1.0 + whole)) << "triangle " << t;
  }
}

namespace
{
/// Runs the core with exact cells on the lattice of one root cell of width 4
/// at `origin` (no shift: the test meshes' features lie on its planes), with
/// MaximumDepth `depth`: failing cells of the tolerance's size, or at the
/// limit, keep the mesh.
tpctest::ContourRun ContourOnLattice(const tpc::MeshSolid& mesh, const Vec3& origin, double tolerance, int depth)
{
  tpctest::SceneBuilder b;
  b.Finish(b.Mesh(mesh));
  const tpc::RootGrid grid = tpctest::SingleRoot(origin, 4.0, depth);
  tpc::SubdivisionParameters p;
  p.HausdorffTolerance = tolerance;
  p.MaximumDepth = depth;
  p.ExactCells = true;
  tpctest::ContourRun r;
  r.Tolerance = tolerance;
  r.Subdivision = tpc::RunTopologyPreservingSubdivision(b.Scene, grid, p);
  r.Extraction = tpc::ExtractSurface(r.Subdivision.Octree, b.Scene);
  r.Embedding = tpc::CheckEmbedding(r.Subdivision.Octree, r.Extraction.Mesh);
  r.Report = tpc::ComputeTopologyReport(r.Extraction.Mesh);
  tpctest::ExpectEmbeddingCheckAgreesWithCgal(r.Embedding, r.Extraction.Mesh);
  return r;
}

void ExpectClosedEmbedded(const tpctest::ContourRun& r, long long components, long long genus, const std::string& what)
{
  SCOPED_TRACE(what);
  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_EQ(r.Extraction.InconsistentCells, 0u);
  EXPECT_TRUE(r.Report.Closed && r.Report.Manifold && r.Report.Oriented);
  EXPECT_TRUE(r.Embedding.Embedded());
  EXPECT_EQ(r.Report.Components, components);
  EXPECT_EQ(r.Report.Genus, genus);
}
} // namespace

TEST(ExactCells, AtTheDepthLimitEveryCellKeepsTheMesh)
{
  // A torus at a depth limit far above the tolerance's level: every surface
  // cell that still fails keeps the mesh, next to cells that passed - closed,
  // manifold, embedded, genus 1, and no cell left unresolved.
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0.013, -0.007, 0.004 }, 1.0, 0.35, 48, 24);
  for (const int depth : { 3, 4, 5 })
  {
    const tpctest::ContourRun r = ContourOnLattice(torus, { -2, -2, -2 }, 0.01, depth);
    EXPECT_GT(r.Subdivision.ExactCells, 0u);
    ExpectClosedEmbedded(r, 1, 1, "depth " + std::to_string(depth));
  }
}

TEST(ExactCells, GenericCubeAndSlabBesideSampledCells)
{
  // A cube and a slab thinner than a cell, off the lattice's planes. At
  // tolerance 0.5 the cells are tested from depth 3 on: cells that pass
  // border cells that keep the mesh (the slab's cells all do).
  const Vec3 shift{ 0.0123, 0.0071, 0.0049 };
  for (const int depth : { 2, 3, 4, 5 })
  {
    const tpc::MeshSolid cube = tpctest::CubeMesh(Vec3{ 1.0, 1.0, 1.0 } + shift, Vec3{ 2.5, 3.0, 2.0 } + shift);
    ExpectClosedEmbedded(ContourOnLattice(cube, { 0, 0, 0 }, 0.5, depth), 1, 0, "cube, depth " + std::to_string(depth));
    const tpc::MeshSolid slab = tpctest::CubeMesh(Vec3{ 0.5, 0.5, 2.01 } + shift, Vec3{ 3.5, 3.0, 2.02 } + shift);
    ExpectClosedEmbedded(ContourOnLattice(slab, { 0, 0, 0 }, 0.5, depth), 1, 0, "slab, depth " + std::to_string(depth));
  }
}

TEST(ExactCells, TiesWithTheLatticeStayConsistent)
{
  // A cube whose faces, edges and corners lie on lattice planes, lines and
  // points (the filter shifts the lattice off such features; here it is
  // not): every tie is decided by the perturbation, alike in every cell, so
  // the surface is closed, manifold and of the right topology. Its pieces
  // next to the features are infinitesimal - points of the moved mesh - and
  // collapse to equal coordinates: the exact check says the surface is not
  // embedded, as CGAL does (CoreContour.h), so the guarantee is not given.
  for (const int depth : { 2, 3, 4, 5 })
  {
    SCOPED_TRACE("depth " + std::to_string(depth));
    const tpc::MeshSolid cube = tpctest::CubeMesh({ 1.0, 1.0, 1.0 }, { 2.5, 3.0, 2.0 });
    const tpctest::ContourRun r = ContourOnLattice(cube, { 0, 0, 0 }, 0.5, depth);
    EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
    EXPECT_EQ(r.Extraction.InconsistentCells, 0u);
    EXPECT_TRUE(r.Report.Closed && r.Report.Manifold && r.Report.Oriented);
    EXPECT_EQ(r.Report.Components, 1);
    EXPECT_EQ(r.Report.Genus, 0);
    EXPECT_FALSE(r.Embedding.Embedded());
    EXPECT_FALSE(tpctest::Guaranteed(r));
    // The blamed cells' triangles have no proven bound (their triangles may
    // leave the cell, which the cell-diagonal bound needs): NaN, as the
    // surface's CertifiedError shows them; every other triangle's is finite.
    tpc::AdaptiveOctree octree = r.Subdivision.Octree;
    for (const std::uint32_t n : r.Embedding.Cells)
    {
      octree.Nodes[n].Reason = octree.Nodes[n].FailedTest = tpc::SplitReason::PatchNotEmbedded; // (as Contour marks them)
    }
    const std::vector<double> bounds = tpc::TriangleErrorBounds(octree, r.Extraction);
    std::size_t unproven = 0;
    for (std::size_t t = 0; t < bounds.size(); ++t)
    {
      const bool blamed = std::find(r.Embedding.Cells.begin(), r.Embedding.Cells.end(),
                            r.Extraction.Mesh.TriangleCell[t]) != r.Embedding.Cells.end();
      EXPECT_EQ(std::isnan(bounds[t]), blamed) << "triangle " << t;
      unproven += blamed ? 1 : 0;
    }
    EXPECT_GT(unproven, 0u);
  }
}

namespace
{
/// Distance from p to triangle (a, b, c), well conditioned for needles: to
/// the plane where p projects inside the triangle, else to the nearest edge.
double DistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  auto toSegment = [&](const Vec3& s, const Vec3& e) {
    const Vec3 d = e - s;
    const double t = std::clamp(tpc::Dot(p - s, d) / tpc::Dot(d, d), 0.0, 1.0);
    return tpc::Norm(p - (s + d * t));
  };
  const Vec3 n = tpc::Cross(b - a, c - a);
  const double height = tpc::Dot(p - a, n) / tpc::Norm(n);
  const Vec3 q = p - tpc::Normalized(n) * height;
  int k = 0;
  for (int i = 1; i < 3; ++i)
  {
    k = std::fabs(n[i]) > std::fabs(n[k]) ? i : k;
  }
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  const int s1 = tpc::Orient2D(a[u], a[v], b[u], b[v], q[u], q[v]), s2 = tpc::Orient2D(b[u], b[v], c[u], c[v], q[u], q[v]),
            s3 = tpc::Orient2D(c[u], c[v], a[u], a[v], q[u], q[v]);
  const bool inside = (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  return inside ? std::fabs(height) : std::min({ toSegment(a, b), toSegment(b, c), toSegment(c, a) });
}
} // namespace

TEST(ExactCells, PatchIsTheMeshWithinRounding)
{
  // The sliver tetrahedron's exact cells: every vertex of their patches lies
  // on the input surface (within rounding), so their two-sided distance to
  // it is rounding-level, far below the tolerance.
  std::vector<Vec3> points = { { -0.249434, -9.94681, 7.66848 }, { -0.503165, 8.89648, 0.896037 },
    { -0.503165, -0.666568, 3.81975 }, { -0.503165, -10.2296, 6.74347 } };
  std::vector<std::array<std::uint32_t, 3>> triangles = { { 0, 2, 1 }, { 0, 3, 2 }, { 0, 1, 3 }, { 1, 2, 3 } };
  const tpc::MeshSolid sliver(points, triangles);
  tpctest::SceneBuilder b;
  b.Finish(b.Mesh(sliver));
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, sliver.Bounds(), 1.0 / 64);
  ASSERT_GT(r.Subdivision.ExactCells, 0u);
  double farthest = 0.0;
  for (std::size_t t = 0; t < r.Extraction.Mesh.Triangles.size(); ++t)
  {
    if (r.Subdivision.Octree.Nodes[r.Extraction.Mesh.TriangleCell[t]].State != tpc::CellState::Exact)
    {
      continue;
    }
    for (const auto v : r.Extraction.Mesh.Triangles[t])
    {
      double nearest = HUGE_VAL;
      for (std::uint32_t k = 0; k < 4; ++k)
      {
        nearest = std::min(nearest, DistanceToTriangle(r.Extraction.Mesh.Points[v], sliver.Vertex(k, 0),
                                      sliver.Vertex(k, 1), sliver.Vertex(k, 2)));
      }
      farthest = std::max(farthest, nearest);
    }
  }
  EXPECT_LT(farthest, 1e-12);
}

TEST(ExactCells, ATolerancePastTheSurfacesSizeStillRemeshes)
{
  // Exact cells count their levels from at most an eighth of the surface's
  // diagonal (ExactCellReferenceSize). Counted from the tolerance, at 64
  // diagonals three levels below its cells one cell held the whole torus and
  // kept all its 9 216 triangles (and the run took 7x as long). A coarse
  // tolerance is a coarse remesh: the tests resolve the torus with a
  // fraction of its triangles, and the surface is guaranteed - at 64
  // diagonals as at one and at a quarter.
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0.013, -0.007, 0.004 }, 1.0, 0.35, 96, 48);
  tpctest::SceneBuilder b;
  b.Finish(b.Mesh(torus));
  for (const double tolerance : { 64.0, 1.0, 0.25 })
  {
    SCOPED_TRACE("tolerance " + std::to_string(tolerance));
    const tpctest::ContourRun r = tpctest::Contour(b.Scene, torus.Bounds(), tolerance);
    EXPECT_TRUE(tpctest::Guaranteed(r));
    EXPECT_EQ(r.Report.Components, 1);
    EXPECT_EQ(r.Report.Genus, 1);
    EXPECT_LT(r.Extraction.Mesh.Triangles.size(), torus.TriangleCount() / 8);
    std::cout << "tolerance " << tolerance << ": " << r.Extraction.Mesh.Triangles.size() << " triangles of "
              << torus.TriangleCount() << ", " << r.Subdivision.ExactCells << " exact cells\n";
  }
  // A cell as small as the tolerance asks that lists at most
  // ExactCellTriangles still keeps them (the reference size moves only the
  // levels where a cell keeps the mesh whatever it lists): a tetrahedron's
  // corners at half its diagonal stay a few triangles each (when that moved
  // too, the tetrahedron came out as 570 triangles).
  // (CGAL's tetrahedron.off, faces turned outward.)
  const std::vector<Vec3> corners = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const tpc::MeshSolid tetrahedron(corners, { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } });
  tpctest::SceneBuilder t;
  t.Finish(t.Mesh(tetrahedron));
  const tpctest::ContourRun r = tpctest::Contour(t.Scene, tetrahedron.Bounds(), 0.5);
  EXPECT_TRUE(tpctest::Guaranteed(r));
  EXPECT_GT(r.Subdivision.ExactCells, 0u);
  EXPECT_LT(r.Extraction.Mesh.Triangles.size(), 200u); // (118)
  std::cout << "tetrahedron at 1/2: " << r.Extraction.Mesh.Triangles.size() << " triangles, "
            << r.Subdivision.ExactCells << " exact cells\n";
}
