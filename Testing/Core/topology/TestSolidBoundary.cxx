// Whether the surface bounds a solid with its normals pointing out
// (SolidBoundary.h): each component's orientation must agree with how many
// others it lies in. Nested boxes, each way round, and a torus.
#include "MeshBuilders.h"
#include "SolidBoundary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
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
/// The sign of the volume the tetrahedron `faces` of `p` encloses, every
/// coordinate scaled exactly by 2^exponent.
int ScaledSign(const Vec3 (&p)[4], const tpc::Triangle (&faces)[4], int exponent)
{
  Vec3 q[4];
  for (int i = 0; i < 4; ++i)
  {
    q[i] = { std::ldexp(p[i][0], exponent), std::ldexp(p[i][1], exponent), std::ldexp(p[i][2], exponent) };
  }
  tpc::EnclosedVolume volume;
  for (const tpc::Triangle& t : faces)
  {
    volume.Add(q, t);
  }
  return volume.Sign();
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

TEST(SolidBoundary, RaysThroughAVertexOrAnEdgeCountRight)
{
  // An octahedral shell around a box-shaped void: the ray from the void's
  // first vertex runs exactly through a vertex of the shell (the void's
  // corner at y = z = 5), or through one of its edges (y = 5, z = 6), where
  // the crossings are decided by the symbolic perturbation. Two components:
  // the void at depth 1 must be turned inward, and only then is it outward.
  const Vec3 c{ 5, 5, 5 };
  const double r = 10;
  const Vec3 tips[6] = { c + Vec3{ r, 0, 0 }, c - Vec3{ r, 0, 0 }, c + Vec3{ 0, r, 0 }, c - Vec3{ 0, r, 0 },
    c + Vec3{ 0, 0, r }, c - Vec3{ 0, 0, r } };
  for (const Vec3& corner : { Vec3{ 4, 5, 5 }, Vec3{ 4, 5, 6 } })
  {
    for (const bool voidTurnedIn : { true, false })
    {
      TriangleMesh mesh;
      for (const Vec3& p : tips)
      {
        mesh.Points.push_back(p);
      }
      for (const std::uint32_t x : { 0u, 1u })
      {
        for (const std::uint32_t y : { 2u, 3u })
        {
          for (const std::uint32_t z : { 4u, 5u })
          {
            tpc::Triangle t{ x, y, z };
            const Vec3 centroid = (tips[x] + tips[y] + tips[z]) * (1.0 / 3.0);
            if (Dot(Cross(tips[y] - tips[x], tips[z] - tips[x]), centroid - c) < 0.0)
            {
              std::swap(t[1], t[2]);
            }
            mesh.Triangles.push_back(t);
          }
        }
      }
      AddBox(mesh, corner, corner + Vec3{ 2, 2, 2 }, voidTurnedIn);
      const Vec3& start = mesh.Points[mesh.Triangles[8][0]];
      ASSERT_TRUE(start[0] == corner[0] && start[1] == corner[1] && start[2] == corner[2])
        << "the ray starts at the void's corner";
      const tpc::OutwardReport report = tpc::CheckOutward(mesh);
      EXPECT_EQ(report.Components, 2);
      EXPECT_EQ(report.Outward(), voidTurnedIn) << corner[2];
      EXPECT_EQ(report.InsideOut, voidTurnedIn ? 0 : 1) << corner[2];
    }
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

TEST(SolidBoundary, TinyCoordinatesNeverGiveTheWrongSign)
{
  // Thin tetrahedra, and the same scaled exactly by 2^-350: there the
  // products underflow, and a bound relative to the terms alone called signs
  // it could not know (about one in eight wrong). Decided at both scales,
  // the signs must agree.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const tpc::Triangle faces[4] = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } };
  int decidedTiny = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    Vec3 p[4];
    for (int i = 0; i < 3; ++i)
    {
      p[i] = { uniform(random), uniform(random), uniform(random) };
    }
    p[3] = (p[0] + p[1] + p[2]) * (1.0 / 3.0) + Cross(p[1] - p[0], p[2] - p[0]) * std::ldexp(uniform(random), -40);
    const int unscaled = ScaledSign(p, faces, 0), tiny = ScaledSign(p, faces, -350);
    decidedTiny += tiny != 0 ? 1 : 0;
    ASSERT_TRUE(tiny == 0 || unscaled == 0 || tiny == unscaled) << "trial " << trial;
  }
  std::cout << decidedTiny << " of 20000 decided at 2^-350\n";
}

TEST(SolidBoundary, UnderflowTimesALongEdgeNeverGivesTheWrongSign)
{
  // A tetrahedron with two corners within 1e-160 of the first and the third
  // 1e10 away, nearly in their plane: the cross products of the short edges
  // underflow, and their errors come multiplied by the long edge. Against
  // the same tetrahedra scaled by 2^600 (nothing underflows there), a sign
  // decided at both scales must agree.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  // (The face away from the first corner starts at the far one: its
  // determinant is d_3 . (d_1 x d_2), the short edges' cross product first.)
  const tpc::Triangle faces[4] = { { 0, 2, 1 }, { 0, 1, 3 }, { 3, 1, 2 }, { 2, 0, 3 } };
  for (int trial = 0; trial < 20000; ++trial)
  {
    const Vec3 b{ uniform(random), uniform(random), uniform(random) };
    const Vec3 c{ uniform(random), uniform(random), uniform(random) };
    const Vec3 inPlane = b * uniform(random) + c * uniform(random);
    Vec3 p[4] = { Vec3{ 0, 0, 0 }, b * std::ldexp(1.0, -530), c * std::ldexp(1.0, -530),
      inPlane * std::ldexp(1.0, 33) + Cross(b, c) * uniform(random) };
    const int reference = ScaledSign(p, faces, 600), tiny = ScaledSign(p, faces, 0);
    ASSERT_TRUE(tiny == 0 || reference == 0 || tiny == reference) << "trial " << trial;
  }
}
