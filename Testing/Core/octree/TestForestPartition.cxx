// A run split into pieces by trees of the root grid (ForestPartition.h):
// each piece subdivides its trees and a ghost ring and extracts its own
// trees; the pieces together are exactly the whole run's surface.
#include "CoreContour.h"
#include "ForestPartition.h"
#include "MeshBuilders.h"
#include "PieceTopology.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

using tpc::Box3;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
using Corner = std::array<double, 3>;
using Triangle = std::array<Corner, 3>;

/// The triangles by their corners' coordinates, each rotated to start at its
/// smallest corner (orientation kept), sorted.
std::vector<Triangle> TrianglesByCoordinates(const tpc::TriangleMesh& mesh)
{
  std::vector<Triangle> out;
  for (const auto& t : mesh.Triangles)
  {
    Triangle c;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& p = mesh.Points[t[k]];
      c[k] = { p[0], p[1], p[2] };
    }
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// One mesh from triangles given by coordinates: equal coordinates are one vertex.
tpc::TriangleMesh Welded(const std::vector<Triangle>& triangles)
{
  tpc::TriangleMesh mesh;
  std::map<Corner, std::uint32_t> ids;
  for (const Triangle& t : triangles)
  {
    std::array<std::uint32_t, 3> tri;
    for (int k = 0; k < 3; ++k)
    {
      const auto it = ids.emplace(t[k], static_cast<std::uint32_t>(mesh.Points.size()));
      if (it.second)
      {
        mesh.Points.push_back({ t[k][0], t[k][1], t[k][2] });
      }
      tri[k] = it.first->second;
    }
    mesh.Triangles.push_back(tri);
  }
  return mesh;
}

/// Runs `scene` (of `components` components and genus `genus`) whole and in
/// `pieces` pieces on a root grid of several trees; checks that the whole
/// run has that topology and that the pieces' triangles are exactly its.
void ExpectPiecesFit(const tpc::ImplicitScene& scene, const Box3& bounds, double relativeTolerance, int pieces,
  int components, int genus)
{
  const Box3 domain = tpctest::GrownDomain(bounds);
  tpc::SubdivisionParameters p;
  p.HausdorffTolerance = relativeTolerance * bounds.Diagonal();
  const tpc::RootGrid grid = tpc::SplitRootCells(tpc::MakeRootGrid(domain, p.HausdorffTolerance, 16), 2, domain);
  p.MaximumDepth = grid.MaxDepth;
  ASSERT_GE(grid.TreeCount(), pieces);

  const tpc::SubdivisionResult whole = tpc::RunTopologyPreservingSubdivision(scene, grid, p);
  ASSERT_EQ(whole.UnresolvedCells, 0u);
  const tpc::ExtractionResult wholeSurface = tpc::ExtractSurface(whole.Octree, scene);
  const tpc::TopologyReport wholeTopology = tpc::ComputeTopologyReport(wholeSurface.Mesh);
  ASSERT_TRUE(wholeTopology.Manifold);
  EXPECT_EQ(wholeTopology.Components, components);
  EXPECT_EQ(wholeTopology.Genus, genus);

  const std::vector<int> pieceOfTree = tpc::PartitionTrees(grid, pieces);
  std::vector<Triangle> merged;
  std::vector<double> seams; // as each piece would send them
  std::size_t fewestNodes = whole.Octree.Nodes.size();
  for (int piece = 0; piece < pieces; ++piece)
  {
    tpc::SubdivisionParameters own = p;
    own.TreeRoles = tpc::TreeRoles(grid, pieceOfTree, piece);
    const tpc::SubdivisionResult part = tpc::RunTopologyPreservingSubdivision(scene, grid, own);
    EXPECT_EQ(part.UnresolvedCells, 0u);
    // (A piece with its ghost ring may cover every tree the surface meets;
    // another then has less.)
    EXPECT_LE(part.Octree.Nodes.size(), whole.Octree.Nodes.size()) << "piece " << piece << " did no more work";
    fewestNodes = std::min(fewestNodes, part.Octree.Nodes.size());
    const tpc::ExtractionResult surface = tpc::ExtractSurface(part.Octree, scene);
    EXPECT_EQ(surface.InconsistentCells, 0u);
    EXPECT_GT(surface.Mesh.Triangles.size(), 0u) << "piece " << piece;
    const std::vector<Triangle> t = TrianglesByCoordinates(surface.Mesh);
    merged.insert(merged.end(), t.begin(), t.end());
    const std::vector<double> sent = tpc::DescribePiece(surface.Mesh).Serialize();
    seams.insert(seams.end(), sent.begin(), sent.end());
  }
  EXPECT_LT(fewestNodes, whole.Octree.Nodes.size()) << "no piece did less work";
  // The report from the pieces' counts and seams alone.
  const tpc::TopologyReport combined = tpc::CombinePieces(tpc::PieceSeams::DeserializeAll(seams));
  EXPECT_TRUE(combined.Closed);
  EXPECT_TRUE(combined.Manifold);
  EXPECT_TRUE(combined.Oriented);
  EXPECT_EQ(combined.Vertices, wholeTopology.Vertices);
  EXPECT_EQ(combined.Edges, wholeTopology.Edges);
  EXPECT_EQ(combined.EulerCharacteristic, wholeTopology.EulerCharacteristic);
  EXPECT_EQ(combined.Components, wholeTopology.Components);
  EXPECT_EQ(combined.Genus, wholeTopology.Genus);
  std::sort(merged.begin(), merged.end());
  EXPECT_TRUE(merged == TrianglesByCoordinates(wholeSurface.Mesh))
    << merged.size() << " triangles in the pieces, " << wholeSurface.Mesh.Triangles.size() << " in the whole run";
  const tpc::TopologyReport m = tpc::ComputeTopologyReport(Welded(merged));
  EXPECT_TRUE(m.Closed);
  EXPECT_TRUE(m.Manifold);
  EXPECT_EQ(m.Components, wholeTopology.Components);
  EXPECT_EQ(m.Genus, wholeTopology.Genus);
}
} // namespace

TEST(ForestPartition, SplitRootCellsKeepsTheLatticeAndCoversTheDomain)
{
  const Box3 domain{ { -1.1, -0.6, -0.3 }, { 1.2, 0.7, 0.4 } };
  const tpc::RootGrid g = tpc::MakeRootGrid(domain, 0.02, 16);
  const tpc::RootGrid s = tpc::SplitRootCells(g, 3, domain);
  EXPECT_EQ(s.MaxDepth, g.MaxDepth - 3);
  EXPECT_GT(s.TreeCount(), 8);
  for (std::uint32_t i : { 0u, 1u, 12345u, 1u << 18 })
  {
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(s.Coordinate(a, i), g.Coordinate(a, i)) << "the same lattice, bit for bit";
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_LE(s.Origin[a], domain.lo[a]);
    EXPECT_GE(s.Origin[a] + s.Dims[a] * s.RootSize, domain.hi[a]);
    EXPECT_LT(s.Origin[a] + (s.Dims[a] - 1) * s.RootSize, domain.hi[a]) << "no tree beyond the domain";
  }
}

TEST(ForestPartition, EveryTreeIsOwnedOnceAndGhostsRingTheOwnTrees)
{
  tpc::RootGrid g;
  g.Dims[0] = 8;
  g.Dims[1] = 3;
  g.Dims[2] = 2;
  const std::vector<int> piece = tpc::PartitionTrees(g, 3);
  std::vector<int> owners(piece.size(), 0);
  for (int p = 0; p < 3; ++p)
  {
    const std::vector<tpc::TreeRole> roles = tpc::TreeRoles(g, piece, p);
    for (std::size_t t = 0; t < roles.size(); ++t)
    {
      owners[t] += roles[t] == tpc::TreeRole::Own;
      const int x = static_cast<int>(t) % 8;
      // Slabs along x: piece p owns the x with floor(3x / 8) = p, i.e. x in
      // [ceil(8p / 3), ceil(8(p + 1) / 3)); ghosts are one tree further.
      const int lo = (8 * p + 2) / 3, hi = (8 * (p + 1) + 2) / 3;
      const tpc::TreeRole expected = x >= lo && x < hi ? tpc::TreeRole::Own
        : (x == lo - 1 || x == hi)                     ? tpc::TreeRole::Ghost
                                                       : tpc::TreeRole::Skipped;
      EXPECT_EQ(roles[t], expected) << "piece " << p << " tree " << t;
    }
  }
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }));
}

TEST(ForestPartition, PiecesOfCurvedCsgFitIntoTheWholeSurface)
{
  // A sphere with a hole (genus 1) and a second sphere apart from it:
  // crossings, face refinements and crack patches on the seams.
  SceneBuilder b;
  b.Finish(SceneBuilder::Union({ SceneBuilder::Difference({ b.Sphere({ 0.1, 0.2, 0.3 }, 0.5),
                                   b.Cylinder({ 0.05, 0.0, 0.25 }, { 0, 1, 0 }, 0.2) }),
    b.Sphere({ 0.9, 0.2, 0.3 }, 0.25) }));
  const Box3 bounds{ { -0.4, -0.3, -0.2 }, { 1.15, 0.7, 0.8 } };
  ExpectPiecesFit(b.Scene, bounds, 0.03, 2, 2, 1);
  ExpectPiecesFit(b.Scene, bounds, 0.03, 3, 2, 1);
}

TEST(ForestPartition, PiecesOfAMeshBooleanFitIntoTheWholeSurface)
{
  SceneBuilder b;
  b.Finish(SceneBuilder::Difference({ b.Mesh(tpctest::TorusMesh({ 0, 0, 0 }, 0.6, 0.25, 48, 24)),
    b.Sphere({ 0.6, 0, 0 }, 0.2) }));
  const Box3 bounds{ { -0.85, -0.85, -0.25 }, { 0.85, 0.85, 0.25 } };
  // (The sphere lies inside the torus's tube: a torus with a cavity.)
  ExpectPiecesFit(b.Scene, bounds, 0.03, 2, 2, 1);
  ExpectPiecesFit(b.Scene, bounds, 0.03, 4, 2, 1);
}
