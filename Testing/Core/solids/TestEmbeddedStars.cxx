// Stars proven embedded (EmbeddedStars.h): which vertices are proven, that a
// proof never hides a pair the exact test would find, and that their count of
// pinched vertices is VertexLinks.h's.
#include "EmbeddedStars.h"
#include "MeshBuilders.h"
#include "SelfIntersection.h"
#include "VertexLinks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using tpc::Vec3;
using Tris = std::vector<std::array<std::uint32_t, 3>>;

namespace
{
/// Vertex 0 at the origin and a fan of triangles (0, k, k + 1) over link
/// points on the unit circle at `degrees`, in that order, closed.
void Fan(const std::vector<double>& degrees, std::vector<Vec3>& points, Tris& triangles)
{
  points = { Vec3(0, 0, 0) };
  for (const double d : degrees)
  {
    const double a = d * M_PI / 180.0;
    points.emplace_back(std::cos(a), std::sin(a), 0.01 * std::sin(3 * a));
  }
  const auto m = static_cast<std::uint32_t>(degrees.size());
  triangles.clear();
  for (std::uint32_t k = 0; k < m; ++k)
  {
    triangles.push_back({ 0, k + 1, (k + 1) % m + 1 });
  }
}

/// Every pair of triangles that the exact test finds meeting improperly.
std::size_t ImproperPairs(const std::vector<Vec3>& p, const Tris& t)
{
  std::size_t n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
  {
    for (std::size_t j = i + 1; j < t.size(); ++j)
    {
      n += tpc::TrianglesMeetImproperly(p.data(), t[i], t[j]) ? 1 : 0;
    }
  }
  return n;
}

bool SharesAVertex(const std::array<std::uint32_t, 3>& a, const std::array<std::uint32_t, 3>& b)
{
  for (const std::uint32_t u : a)
  {
    for (const std::uint32_t v : b)
    {
      if (u == v)
      {
        return true;
      }
    }
  }
  return false;
}

tpc::EmbeddedStars Stars(const std::vector<Vec3>& p, const Tris& t)
{
  return tpc::EmbeddedStars(p.data(), p.size(), t.data(), t.size());
}

/// Two fans of five triangles sharing vertex 0 (a bow tie), the second a
/// copy of the first's rim lifted by 1 along z: two cycles around vertex 0.
void BowTie(std::vector<Vec3>& p, Tris& t)
{
  Fan({ 0, 72, 144, 216, 288 }, p, t);
  const auto n = static_cast<std::uint32_t>(p.size());
  for (const Vec3& q : std::vector<Vec3>(p.begin() + 1, p.end()))
  {
    p.push_back(q + Vec3(0, 0, 1));
  }
  const Tris first = t;
  for (const auto& f : first)
  {
    t.push_back({ 0, f[1] + n - 1, f[2] + n - 1 });
  }
}
} // namespace

TEST(EmbeddedStars, AFanWindingOnceIsProvenOneWindingTwiceIsNot)
{
  std::vector<Vec3> p;
  Tris t;
  // A pentagon's fan: every wedge 72 degrees, once around.
  Fan({ 0, 72, 144, 216, 288 }, p, t);
  EXPECT_TRUE(Stars(p, t).IsProven(0));
  EXPECT_EQ(ImproperPairs(p, t), 0u);
  // A pentagram's: every wedge 144 degrees, each of the same orientation,
  // twice around - its triangles overlap.
  Fan({ 0, 144, 288, 72, 216 }, p, t);
  const tpc::EmbeddedStars pentagram = Stars(p, t);
  EXPECT_FALSE(pentagram.IsProven(0));
  EXPECT_GT(ImproperPairs(p, t), 0u);
  for (std::size_t i = 0; i < t.size(); ++i)
  {
    for (std::size_t j = i + 1; j < t.size(); ++j)
    {
      EXPECT_FALSE(pentagram.ProveProper(t[i], t[j]));
    }
  }
  // One triangle walked the other way: no cycle of link edges.
  Fan({ 0, 72, 144, 216, 288 }, p, t);
  std::swap(t[2][1], t[2][2]);
  EXPECT_FALSE(Stars(p, t).IsProven(0));
  // Twice around with a link point exactly on the first one's ray (the
  // half-open wedges: counted once, not zero times): (1, 0), (-1, 2),
  // (-1, -2), (2, 0), (-2, 3), (-2, -3), every wedge counter-clockwise.
  p = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(-1, 2, 0), Vec3(-1, -2, 0), Vec3(2, 0, 0), Vec3(-2, 3, 0),
    Vec3(-2, -3, 0) };
  t.clear();
  for (std::uint32_t k = 0; k < 6; ++k)
  {
    t.push_back({ 0, k + 1, (k + 1) % 6 + 1 });
  }
  EXPECT_FALSE(Stars(p, t).IsProven(0));
  EXPECT_GT(ImproperPairs(p, t), 0u);
  // A wedge of more than a half turn (the other orientation).
  Fan({ 0, 90, 300 }, p, t);
  EXPECT_FALSE(Stars(p, t).IsProven(0));
}

TEST(EmbeddedStars, PinchedAndSharpVerticesProveNothing)
{
  // Two fans sharing vertex 0 (a bow tie): two cycles.
  std::vector<Vec3> p;
  Tris t;
  BowTie(p, t);
  EXPECT_FALSE(Stars(p, t).IsProven(0));
  // A cube's corners: no axis sees the three faces from one side.
  const tpc::MeshSolid cube = tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 });
  const tpc::EmbeddedStars corners = Stars(cube.Points(), cube.Triangles());
  EXPECT_EQ(corners.ProvenCount(), 0u);
  EXPECT_EQ(tpc::CountSelfIntersections(cube.Points(), cube.Triangles()), 0u);
}

TEST(EmbeddedStars, SmoothClosedMeshesAreProvenEverywhere)
{
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0, 0, 0 }, 1.0, 3);
  EXPECT_EQ(Stars(sphere.Points(), sphere.Triangles()).ProvenCount(), sphere.Points().size());
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, 0.6, 0.25, 48, 24);
  EXPECT_EQ(Stars(torus.Points(), torus.Triangles()).ProvenCount(), torus.Points().size());
}

TEST(EmbeddedStars, NoProofHidesAPairTheExactTestFinds)
{
  // Spheres whose vertices are pushed at random, some far enough to fold
  // their stars over their neighbours: the count with
  // the stars' proofs (CountSelfIntersections) against every pair tested
  // exactly, and each proof against the exact test of its pairs.
  std::mt19937 rng(7);
  const tpc::MeshSolid base = tpctest::SphereMesh({ 0, 0, 0 }, 1.0, 2);
  int folded = 0, proven = 0, neighboursMeeting = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    std::vector<Vec3> p = base.Points();
    const Tris& t = base.Triangles();
    // (Edges are about 0.3 long: a push of up to 0.6 across moves a vertex
    // past its neighbours.)
    std::uniform_real_distribution<double> push(-0.6, 0.6);
    std::uniform_int_distribution<std::size_t> pick(0, p.size() - 1);
    for (int k = 0; k < 2 + trial % 8; ++k)
    {
      Vec3& q = p[pick(rng)];
      const double x = push(rng), y = push(rng), z = push(rng); // (in this order on every compiler)
      q = q + Vec3(x, y, z);
    }
    const std::size_t all = ImproperPairs(p, t);
    ASSERT_EQ(tpc::CountSelfIntersections(p, t, 1u << 30), all) << "trial " << trial;
    const tpc::EmbeddedStars stars = Stars(p, t);
    for (std::size_t i = 0; i < t.size(); ++i)
    {
      for (std::size_t j = i + 1; j < t.size(); ++j)
      {
        const bool improper = tpc::TrianglesMeetImproperly(p.data(), t[i], t[j]);
        neighboursMeeting += improper && SharesAVertex(t[i], t[j]) ? 1 : 0;
        if (stars.ProveProper(t[i], t[j]))
        {
          ++proven;
          ASSERT_FALSE(improper) << "trial " << trial;
        }
      }
    }
    folded += all > 0 ? 1 : 0;
  }
  EXPECT_GT(folded, 20);            // (the pushes do fold stars,
  EXPECT_GT(neighboursMeeting, 20); // their own triangles meeting too)
  EXPECT_GT(proven, 10000);
}

TEST(EmbeddedStars, TheirPinchedVertexCountIsTheLinksOwn)
{
  // EmbeddedStars::CountNonManifoldVertices passes over the vertices whose
  // link it found to be one cycle: the count must be VertexLinks.h's, which
  // looks at every link - on a cube (one cycle, no star proven: none
  // pinched), a sphere with a triangle turned over (its corners' links are
  // one cycle, not one oriented cycle: none pinched), a bow tie and two
  // tetrahedra sharing a corner (pinched), and pushed spheres.
  const auto both = [](const std::vector<Vec3>& p, const Tris& t) {
    std::int64_t byStars = 0, byLinks = 0;
    EXPECT_TRUE(Stars(p, t).CountNonManifoldVertices(byStars));
    EXPECT_TRUE(tpc::CountNonManifoldVertices(t.data(), t.size(), p.size(), byLinks));
    EXPECT_EQ(byStars, byLinks);
    return byStars;
  };
  const tpc::MeshSolid cube = tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 });
  EXPECT_EQ(both(cube.Points(), cube.Triangles()), 0);
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0, 0, 0 }, 1.0, 2);
  Tris turned = sphere.Triangles();
  std::swap(turned[5][1], turned[5][2]);
  EXPECT_EQ(both(sphere.Points(), turned), 0);
  const std::vector<Vec3> corners{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(-1, 0, 0),
    Vec3(0, -1, 0), Vec3(0, 0, -1) };
  const Tris tetrahedra{ { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 }, { 0, 4, 5 }, { 0, 6, 4 }, { 0, 5, 6 },
    { 4, 6, 5 } };
  EXPECT_EQ(both(corners, tetrahedra), 1);
  std::vector<Vec3> p;
  Tris t;
  BowTie(p, t);
  EXPECT_GE(both(p, t), 1); // (vertex 0; the open fans' rims are no cycles either)
  std::mt19937 rng(11);
  for (int trial = 0; trial < 10; ++trial)
  {
    std::vector<Vec3> pushed = sphere.Points();
    std::uniform_real_distribution<double> push(-0.6, 0.6);
    for (Vec3& q : pushed)
    {
      const double x = push(rng), y = push(rng), z = push(rng);
      q = q + Vec3(x, y, z) * (trial / 10.0);
    }
    EXPECT_EQ(both(pushed, sphere.Triangles()), 0) << "trial " << trial;
  }
}
