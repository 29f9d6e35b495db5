// The topology report (TopologyReport.h) and the pieces' report
// (PieceTopology.h), on meshes built to break one property each: the
// guarantee counts on every check here, so each must see its defect.
#include "MeshBuilders.h"
#include "PieceTopology.h"
#include "TopologyReport.h"

#include <gtest/gtest.h>

using tpc::TopologyReport;
using tpc::TriangleMesh;
using tpc::Vec3;

namespace
{
/// The closed triangle mesh of a solid.
TriangleMesh AsMesh(const tpc::MeshSolid& solid)
{
  TriangleMesh m;
  for (const Vec3& p : solid.Points())
  {
    m.Points.push_back(p);
  }
  for (const tpc::Triangle& t : solid.Triangles())
  {
    m.Triangles.push_back(t);
  }
  return m;
}

/// `b`'s triangles and points appended to `a` (a second component).
TriangleMesh Joined(TriangleMesh a, const TriangleMesh& b)
{
  const auto offset = static_cast<std::uint32_t>(a.Points.size());
  for (const Vec3& p : b.Points)
  {
    a.Points.push_back(p);
  }
  for (tpc::Triangle t : b.Triangles)
  {
    for (auto& v : t)
    {
      v += offset;
    }
    a.Triangles.push_back(t);
  }
  return a;
}

TriangleMesh UnitCube()
{
  return AsMesh(tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 }));
}

void ExpectClosedManifoldOriented(const TopologyReport& r)
{
  EXPECT_TRUE(r.Closed);
  EXPECT_TRUE(r.Manifold);
  EXPECT_TRUE(r.Oriented);
  EXPECT_EQ(r.BoundaryEdges, 0);
  EXPECT_EQ(r.NonManifoldEdges, 0);
  EXPECT_EQ(r.NonManifoldVertices, 0);
}
} // namespace

TEST(TopologyReport, CubeSphereAndTorusHaveTheirGenus)
{
  const TopologyReport cube = tpc::ComputeTopologyReport(UnitCube());
  ExpectClosedManifoldOriented(cube);
  EXPECT_EQ(cube.Vertices, 8);
  EXPECT_EQ(cube.Edges, 18);
  EXPECT_EQ(cube.Faces, 12);
  EXPECT_EQ(cube.EulerCharacteristic, 2);
  EXPECT_EQ(cube.Components, 1);
  EXPECT_EQ(cube.Genus, 0);
  EXPECT_NEAR(cube.SignedVolume, 1.0, 1e-12);
  const TopologyReport torus = tpc::ComputeTopologyReport(AsMesh(tpctest::TorusMesh({ 0, 0, 0 }, 1.0, 0.3, 12, 8)));
  ExpectClosedManifoldOriented(torus);
  EXPECT_EQ(torus.EulerCharacteristic, 0);
  EXPECT_EQ(torus.Genus, 1);
  EXPECT_GT(torus.SignedVolume, 0.0);
}

TEST(TopologyReport, TwoComponentsSumTheirGenera)
{
  const TriangleMesh two =
    Joined(UnitCube(), AsMesh(tpctest::TorusMesh({ 5, 0, 0 }, 1.0, 0.3, 12, 8)));
  const TopologyReport r = tpc::ComputeTopologyReport(two);
  ExpectClosedManifoldOriented(r);
  EXPECT_EQ(r.Components, 2);
  EXPECT_EQ(r.EulerCharacteristic, 2);
  EXPECT_EQ(r.Genus, 1);
}

TEST(TopologyReport, BowTieVertexIsNotManifold)
{
  // Two cubes touching at one corner, the corner one vertex: every edge has
  // two triangles, but the triangles around that vertex form two cycles.
  TriangleMesh bowTie = Joined(UnitCube(), AsMesh(tpctest::CubeMesh({ 1, 1, 1 }, { 2, 2, 2 })));
  // Cube 1's corner (1, 1, 1) is vertex 7; cube 2's (1, 1, 1) is vertex 8 + 0.
  for (tpc::Triangle& t : bowTie.Triangles)
  {
    for (auto& v : t)
    {
      v = v == 8 ? 7 : v;
    }
  }
  const TopologyReport r = tpc::ComputeTopologyReport(bowTie);
  EXPECT_EQ(r.BoundaryEdges, 0);
  EXPECT_EQ(r.NonManifoldEdges, 0);
  EXPECT_EQ(r.NonManifoldVertices, 1);
  EXPECT_TRUE(r.Closed);
  EXPECT_FALSE(r.Manifold);
  EXPECT_EQ(r.Genus, -1);
  EXPECT_EQ(r.Components, 1);
}

TEST(TopologyReport, FlippedTriangleIsNotOriented)
{
  TriangleMesh flipped = UnitCube();
  std::swap(flipped.Triangles[3][1], flipped.Triangles[3][2]);
  const TopologyReport r = tpc::ComputeTopologyReport(flipped);
  EXPECT_TRUE(r.Closed);
  EXPECT_TRUE(r.Manifold);
  EXPECT_FALSE(r.Oriented);
  EXPECT_EQ(r.Genus, -1);
}

TEST(TopologyReport, OpenFanHasABoundary)
{
  // Four triangles around a centre, not closed: four boundary edges.
  TriangleMesh fan;
  fan.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 } };
  fan.Triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 1 } };
  const TopologyReport r = tpc::ComputeTopologyReport(fan);
  EXPECT_EQ(r.BoundaryEdges, 4);
  EXPECT_EQ(r.Edges, 8);
  EXPECT_FALSE(r.Closed);
  EXPECT_FALSE(r.Manifold);
  EXPECT_EQ(r.Genus, -1);
  // The cube with one triangle removed has the three edges of the hole.
  TriangleMesh holed = UnitCube();
  holed.Triangles[5] = holed.Triangles[11];
  holed.Triangles.resize(11);
  EXPECT_EQ(tpc::ComputeTopologyReport(holed).BoundaryEdges, 3);
}

TEST(TopologyReport, NonManifoldEdgeIsCounted)
{
  // A third triangle on one edge of a closed cube.
  TriangleMesh fin = UnitCube();
  fin.Points.push_back({ 0.5, -1.0, -1.0 });
  fin.Triangles.push_back({ 0, 1, 8 });
  const TopologyReport r = tpc::ComputeTopologyReport(fin);
  EXPECT_EQ(r.NonManifoldEdges, 1);
  EXPECT_EQ(r.BoundaryEdges, 2);
  EXPECT_FALSE(r.Manifold);
  EXPECT_EQ(r.Genus, -1);
}

TEST(TopologyReport, DegenerateTriangleIsNotManifold)
{
  TriangleMesh degenerate = UnitCube();
  degenerate.Triangles.push_back({ 0, 0, 1 });
  const TopologyReport r = tpc::ComputeTopologyReport(degenerate);
  EXPECT_EQ(r.DegenerateTriangles, 1);
  EXPECT_FALSE(r.Manifold);
}

TEST(TopologyReport, AbortStopsEarlyWithoutAVerdict)
{
  const TopologyReport r =
    tpc::ComputeTopologyReport(UnitCube(), tpc::SequentialFor, [](double) { return true; });
  EXPECT_FALSE(r.Closed);
  EXPECT_EQ(r.Genus, -1);
}

TEST(PieceTopology, PiecesOfATorusCombineToTheWholeReport)
{
  // The torus cut into two pieces by its triangles' index (the pieces'
  // seam vertices are bit-identical, as in a split run).
  const TriangleMesh torus = AsMesh(tpctest::TorusMesh({ 0, 0, 0 }, 1.0, 0.3, 12, 8));
  TriangleMesh pieces[2];
  for (auto& piece : pieces)
  {
    piece.Points = torus.Points;
  }
  for (std::size_t t = 0; t < torus.Triangles.size(); ++t)
  {
    pieces[t < torus.Triangles.size() / 3 ? 0 : 1].Triangles.push_back(torus.Triangles[t]);
  }
  std::vector<double> sent;
  for (const auto& piece : pieces)
  {
    const std::vector<double> one = tpc::DescribePiece(piece).Serialize();
    sent.insert(sent.end(), one.begin(), one.end());
  }
  const TopologyReport combined = tpc::CombinePieces(tpc::PieceSeams::DeserializeAll(sent));
  const TopologyReport whole = tpc::ComputeTopologyReport(torus);
  EXPECT_TRUE(combined.Closed);
  EXPECT_TRUE(combined.Oriented);
  EXPECT_EQ(combined.Vertices, whole.Vertices);
  EXPECT_EQ(combined.Edges, whole.Edges);
  EXPECT_EQ(combined.Components, 1);
  EXPECT_EQ(combined.Genus, 1);
  // Without its second piece the first is open along the seam.
  const TopologyReport alone = tpc::CombinePieces({ tpc::DescribePiece(pieces[0]) });
  EXPECT_FALSE(alone.Closed);
  EXPECT_GT(alone.BoundaryEdges, 0);
}

TEST(PieceTopology, FlippedTriangleInAPieceIsNotOriented)
{
  TriangleMesh cube = UnitCube();
  std::swap(cube.Triangles[0][1], cube.Triangles[0][2]);
  const TopologyReport r = tpc::CombinePieces({ tpc::DescribePiece(cube) });
  EXPECT_TRUE(r.Closed);
  EXPECT_FALSE(r.Oriented);
}
