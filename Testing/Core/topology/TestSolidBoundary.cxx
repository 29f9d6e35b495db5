// Whether the surface bounds a solid with its normals pointing out
// (SolidBoundary.h): each component's orientation must agree with how many
// others it lies in. Nested boxes, each way round, and a torus.
#include "MeshBuilders.h"
#include "SolidBoundary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

using tpc::TriangleMesh;
using tpc::Vec3;

namespace
{
/// A box, its normals out (or in, `inward`), appended to `mesh`.
void AddBox(TriangleMesh& mesh, const Vec3& lo, const Vec3& hi, bool inward)
{
  const tpc::MeshSolid box = tpctest::CubeMesh(lo, hi);
  const auto offset = static_cast<std::uint32_t>(mesh.Points.size());
  for (const Vec3& p : box.Points())
  {
    mesh.Points.push_back(p);
  }
  for (tpc::Triangle t : box.Triangles())
  {
    for (std::uint32_t& v : t)
    {
      v += offset;
    }
    if (inward)
    {
      std::swap(t[1], t[2]);
    }
    mesh.Triangles.push_back(t);
  }
}
} // namespace

TEST(SolidBoundary, EachComponentPointsOutOfTheSolid)
{
  // Shell, void in it, island in the void, and a second shell beside: the
  // nesting depths 0, 1, 2, 0, so out, in, out, out.
  const Vec3 shell[2] = { { 0, 0, 0 }, { 10, 10, 10 } };
  const Vec3 cavity[2] = { { 1, 1, 1 }, { 9, 9, 9 } };
  const Vec3 island[2] = { { 3, 3, 3 }, { 6, 6, 6 } };
  const Vec3 beside[2] = { { 20, 0, 0 }, { 21, 1, 1 } };
  const bool right[4] = { false, true, false, false };
  {
    TriangleMesh mesh;
    AddBox(mesh, shell[0], shell[1], right[0]);
    AddBox(mesh, cavity[0], cavity[1], right[1]);
    AddBox(mesh, island[0], island[1], right[2]);
    AddBox(mesh, beside[0], beside[1], right[3]);
    const tpc::OutwardReport r = tpc::CheckOutward(mesh);
    EXPECT_EQ(r.Components, 4);
    EXPECT_EQ(r.InsideOut, 0);
    EXPECT_EQ(r.Undecided, 0);
    EXPECT_TRUE(r.Outward());
  }
  // Each one turned over in turn: that one, and only it, is inside out
  // (the total volume stays positive in three of the four: a total would
  // not see them).
  for (int wrong = 0; wrong < 4; ++wrong)
  {
    TriangleMesh mesh;
    const Vec3* boxes[4] = { shell, cavity, island, beside };
    for (int k = 0; k < 4; ++k)
    {
      AddBox(mesh, boxes[k][0], boxes[k][1], right[k] != (k == wrong));
    }
    const tpc::OutwardReport r = tpc::CheckOutward(mesh);
    EXPECT_EQ(r.InsideOut, 1) << "box " << wrong << " turned over";
    EXPECT_FALSE(r.Outward());
  }
}

TEST(SolidBoundary, OneComponentNeedsOnlyItsVolume)
{
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, 0.6, 0.25, 24, 12);
  TriangleMesh mesh;
  for (const Vec3& p : torus.Points())
  {
    mesh.Points.push_back(p);
  }
  for (const tpc::Triangle& t : torus.Triangles())
  {
    mesh.Triangles.push_back(t);
  }
  EXPECT_TRUE(tpc::CheckOutward(mesh).Outward());
  for (tpc::Triangle& t : mesh.Triangles)
  {
    std::swap(t[1], t[2]);
  }
  const tpc::OutwardReport r = tpc::CheckOutward(mesh);
  EXPECT_EQ(r.Components, 1);
  EXPECT_EQ(r.InsideOut, 1);
}

TEST(SolidBoundary, AVolumeWithinItsRoundingIsUndecided)
{
  // A unit square slab 1e-17 thick, turned off the axes: each determinant's
  // terms are about 1, their sum about 1e-17, below what rounding can
  // decide - not called outward. The same slab 0.1 thick is.
  for (const double thickness : { 1e-17, 0.1 })
  {
    TriangleMesh mesh;
    AddBox(mesh, { 0, 0, 0 }, { 1, 1, thickness }, false);
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (Vec3& p : mesh.Points)
    {
      const Vec3 q = p;
      p = { c * q[0] - s * q[2], q[1], s * q[0] + c * q[2] };
      p = { p[0], c * p[1] - s * p[2], s * p[1] + c * p[2] };
    }
    const tpc::OutwardReport r = tpc::CheckOutward(mesh);
    EXPECT_EQ(r.Undecided, thickness < 1e-3 ? 1 : 0) << thickness;
    EXPECT_EQ(r.Outward(), thickness > 1e-3) << thickness;
  }
}
