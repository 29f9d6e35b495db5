// Vertices split along creases for shading (CreaseSplit.h): the positions,
// and so the surface, stay; each wedge between creases gets its own point and
// normal; a smooth surface is left as it is.
#include "CreaseSplit.h"
#include "MeshBuilders.h"
#include "MeshEdges.h"

#include <gtest/gtest.h>

#include <set>

namespace
{
/// A MeshSolid as the extraction's mesh, each point's normal the
/// `normal(point)` given.
template <typename Normal>
tpc::TriangleMesh AsTriangleMesh(const tpc::MeshSolid& solid, Normal&& normal)
{
  tpc::TriangleMesh mesh;
  for (const tpc::Vec3& p : solid.Points())
  {
    mesh.Points.push_back(p);
    mesh.Normals.push_back(normal(p));
  }
  for (const auto& t : solid.Triangles())
  {
    mesh.Triangles.push_back(t);
  }
  return mesh;
}

tpc::Vec3 UnitNormal(const tpc::TriangleMesh& mesh, const tpc::Triangle& t)
{
  return tpc::Normalized(
    tpc::Cross(mesh.Points[t[1]] - mesh.Points[t[0]], mesh.Points[t[2]] - mesh.Points[t[0]]));
}
} // namespace

TEST(CreaseSplit, CubeCornersGetOnePointPerFaceWithTheFacesNormal)
{
  const tpc::MeshSolid cube = tpctest::CubeMesh({ 0, 0, 0 }, { 1, 2, 3 });
  tpc::TriangleMesh mesh = AsTriangleMesh(cube, [](const tpc::Vec3&) { return tpc::Vec3{ 1, 0, 0 }; });
  std::vector<std::uint32_t> surfacePoint;
  tpc::SplitAtCreases(mesh, 30.0, surfacePoint);

  // Three faces meet at each corner; the face diagonals are flat (0 degrees).
  ASSERT_EQ(mesh.Points.size(), 24u);
  ASSERT_EQ(surfacePoint.size(), 24u);
  ASSERT_EQ(mesh.Normals.size(), 24u);
  for (std::uint32_t v = 0; v < 8; ++v)
  {
    EXPECT_EQ(surfacePoint[v], v); // the originals keep their ids
  }
  std::set<std::pair<std::uint32_t, int>> cornerFaces;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const tpc::Triangle& tri = mesh.Triangles[t];
    const tpc::Vec3 n = UnitNormal(mesh, tri);
    for (int k = 0; k < 3; ++k)
    {
      // Same triangle on the closed surface, same positions.
      EXPECT_EQ(surfacePoint[tri[k]], cube.Triangles()[t][k]);
      EXPECT_EQ(mesh.Points[tri[k]][0], cube.Points()[cube.Triangles()[t][k]][0]);
      // Every point of a face carries exactly the face's normal.
      EXPECT_NEAR(tpc::Dot(mesh.Normals[tri[k]], n), 1.0, 1e-12);
    }
  }
  // The two triangles of a face share their diagonal's points: 4 points per face.
  std::set<std::uint32_t> used;
  for (const auto& tri : mesh.Triangles)
  {
    used.insert(tri.begin(), tri.end());
  }
  EXPECT_EQ(used.size(), 24u);
}

TEST(CreaseSplit, AboveTheCreaseAngleNothingSplits)
{
  // A cube's edges are 90-degree creases: at 91 degrees none is a crease.
  const tpc::MeshSolid cube = tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 });
  tpc::TriangleMesh mesh = AsTriangleMesh(cube, [](const tpc::Vec3& p) { return p; });
  std::vector<std::uint32_t> surfacePoint;
  tpc::SplitAtCreases(mesh, 91.0, surfacePoint);
  EXPECT_EQ(mesh.Points.size(), 8u);
  for (std::uint32_t v = 0; v < 8; ++v)
  {
    EXPECT_EQ(surfacePoint[v], v);
    EXPECT_EQ(mesh.Normals[v][1], cube.Points()[v][1]); // normals kept
  }
}

TEST(CreaseSplit, SmoothSurfaceKeepsItsPointsAndNormals)
{
  // A sphere of 1 280 triangles: neighbours differ by about 10 degrees.
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0, 0, 0 }, 1.0, 3);
  tpc::TriangleMesh mesh = AsTriangleMesh(sphere, [](const tpc::Vec3& p) { return tpc::Normalized(p); });
  const tpc::TriangleMesh before = mesh;
  std::vector<std::uint32_t> surfacePoint;
  tpc::SplitAtCreases(mesh, 30.0, surfacePoint);
  ASSERT_EQ(mesh.Points.size(), before.Points.size());
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    EXPECT_EQ(mesh.Triangles[t], before.Triangles[t]);
  }
  for (std::size_t v = 0; v < mesh.Points.size(); ++v)
  {
    EXPECT_EQ(mesh.Normals[v][2], before.Normals[v][2]);
  }
  // At a hundredth of a degree every edge is a crease: each point splits into
  // one point per triangle around it (5 or 6), so every triangle has points
  // of its own.
  tpc::SplitAtCreases(mesh, 0.01, surfacePoint);
  EXPECT_EQ(mesh.Points.size(), 3 * mesh.Triangles.size());
}
