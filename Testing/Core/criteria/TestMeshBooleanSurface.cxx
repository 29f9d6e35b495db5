// S in a cell where meshes meet, bounded from both sides
// (MeshBooleanSurface.h), against brute force: every piece said to be on S
// is (the solid's sign changes across it) and crosses no other mesh's
// triangle, every point of S in the cell lies on a covering piece while
// points of the meshes off S (one mesh inside another solid) are left out,
// and the crease segments lie on two meshes - for two meshes crossing in
// every operation, at a grazing angle, and three meshes; which expressions
// are mesh Booleans; the patch measured against each side in its
// direction; the separating-axis test proves apart only polygons farther
// apart than the margin asked.
#include "MeshBooleanSurface.h"
#include "MeshBuilders.h"
#include "MeshCellError.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

using tpc::Box3;
using tpc::CsgTerm;
using tpc::MeshSolid;
using tpc::PointSpan;
using tpc::Vec3;

namespace
{
/// Whether `x` is on S by brute force: the solid's exact sign differs a
/// hair away on both sides along `normal` (unit).
bool OnSurfaceByBruteForce(const tpctest::Scene& scene, const Vec3& x, const Vec3& normal)
{
  constexpr double Hair = 1e-7;
  return scene.Expression->IsInside(x + normal * Hair, scene.Primitives) !=
    scene.Expression->IsInside(x - normal * Hair, scene.Primitives);
}

/// The distance from `x` to mesh `m`'s surface.
double MeshDistance(const MeshSolid& m, const Vec3& x)
{
  tpc::TriangleList all(m.TriangleCount());
  for (std::uint32_t t = 0; t < all.size(); ++t)
  {
    all[t] = t;
  }
  return std::fabs(m.ApproximateSignedDistance(x, all));
}

/// The least distance from `x` to a polygon of `set`.
double SetDistance(const tpc::PolygonSet& set, const Vec3& x)
{
  double nearest = HUGE_VAL;
  for (const tpc::ConvexPolygon& q : set)
  {
    nearest = std::min(nearest, tpc::PolygonDistance(x, q));
  }
  return nearest;
}

/// Whether segment [p, q] crosses triangle `t` (in floating point: the
/// pieces checked are proven apart by far more than its rounding).
bool SegmentCrossesTriangle(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& t)
{
  const Vec3 n = tpc::Cross(t[1] - t[0], t[2] - t[0]);
  const double sp = tpc::Dot(n, p - t[0]), sq = tpc::Dot(n, q - t[0]);
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0) || sp == sq)
  {
    return false; // (on one side, or in the plane: coplanar pieces are never decided)
  }
  const Vec3 x = p + (q - p) * (sp / (sp - sq));
  for (int k = 0; k < 3; ++k)
  {
    if (tpc::Dot(n, tpc::Cross(t[(k + 1) % 3] - t[k], x - t[k])) < 0)
    {
      return false;
    }
  }
  return true;
}

/// Whether the convex polygon `q` and triangle `t` meet: an edge of one
/// crosses the other (fan triangles of `q`).
bool PolygonMeetsTriangle(const PointSpan& q, const std::array<Vec3, 3>& t)
{
  for (std::size_t k = 0; k < q.size(); ++k)
  {
    if (SegmentCrossesTriangle(q[k], q[(k + 1) % q.size()], t))
    {
      return true;
    }
  }
  for (std::size_t k = 1; k + 1 < q.size(); ++k)
  {
    for (int e = 0; e < 3; ++e)
    {
      if (SegmentCrossesTriangle(t[e], t[(e + 1) % 3], { q[0], q[k], q[k + 1] }))
      {
        return true;
      }
    }
  }
  return false;
}

struct Tally
{
  int Cells = 0, OnChecked = 0, ApartChecked = 0, CoveredChecked = 0, OffSurfaceLeftOut = 0, Creases = 0;
};

/// Checks S's two sides in every cell of a 8^3 grid over [-1, 1]^3 where
/// the scene's meshes meet (header).
void CheckEveryCell(const tpctest::Scene& scene, Tally& tally)
{
  constexpr int N = 8;
  constexpr double Away = 1e-5;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < N * N * N; ++i)
  {
    const Vec3 lo(-1.0 + 2.0 * (i % N) / N, -1.0 + 2.0 * (i / N % N) / N, -1.0 + 2.0 * (i / N / N) / N);
    const Box3 cell{ lo, lo + Vec3(2.0 / N, 2.0 / N, 2.0 / N) };
    const auto pruned = tpc::CsgExpression::Prune(scene.Expression, cell, scene.Primitives);
    if (pruned.Sign != tpc::RegionSign::Mixed || !tpc::IsMeshBoolean(*pruned.Expression))
    {
      continue;
    }
    tpc::MeshBooleanSurface surface;
    std::vector<tpc::CreaseSegment> creases;
    ASSERT_TRUE(tpc::MeshBooleanSurfaceInCell(*pruned.Expression, scene.Primitives, cell, 1.0 / 256, 4096,
      surface, &creases));
    ++tally.Cells;
    const std::vector<tpc::CsgLeaf> leaves = pruned.Expression->Leaves();
    ASSERT_GE(leaves.size(), 2u);
    const auto meshOf = [&](std::size_t leaf) -> const MeshSolid& {
      return scene.Primitives.Meshes[leaves[leaf].Primitive];
    };
    // (Points within Away of another mesh than their own are not checked:
    // the brute-force sign test needs room.)
    const auto awayFromTheOthers = [&](std::size_t leaf, const Vec3& x) {
      for (std::size_t other = 0; other < leaves.size(); ++other)
      {
        if (other != leaf && MeshDistance(meshOf(other), x) <= Away)
        {
          return false;
        }
      }
      return true;
    };
    const auto leafOf = [&](const Vec3& x) {
      std::size_t nearest = 0;
      for (std::size_t leaf = 1; leaf < leaves.size(); ++leaf)
      {
        nearest = MeshDistance(meshOf(leaf), x) < MeshDistance(meshOf(nearest), x) ? leaf : nearest;
      }
      return nearest;
    };
    // Each piece on S crosses no other mesh's triangle in the cell (decided
    // with exact signs a margin away from them: it must not even touch).
    for (const tpc::ConvexPolygon& q : surface.OnSurface)
    {
      const std::size_t own = leafOf(q.Points[0]);
      for (std::size_t other = 0; other < leaves.size(); ++other)
      {
        for (const std::uint32_t t : other == own ? tpc::TriangleList() : *leaves[other].Triangles)
        {
          const MeshSolid& m = meshOf(other);
          EXPECT_FALSE(PolygonMeetsTriangle(q.Points, { m.Vertex(t, 0), m.Vertex(t, 1), m.Vertex(t, 2) }))
            << "cell " << i;
          ++tally.ApartChecked;
        }
      }
    }
    // On S: the centroid and points towards each corner of every piece.
    for (const tpc::ConvexPolygon& q : surface.OnSurface)
    {
      Vec3 centroid;
      for (const Vec3& p : q.Points)
      {
        centroid += p * (1.0 / static_cast<double>(q.Points.size()));
      }
      for (std::size_t k = 0; k <= q.Points.size(); ++k)
      {
        const Vec3 x = k == 0 ? centroid : centroid + (q.Points[k - 1] - centroid) * 0.8;
        if (q.TwiceArea > 1e-12 && awayFromTheOthers(leafOf(x), x))
        {
          EXPECT_TRUE(OnSurfaceByBruteForce(scene, x, q.Normal)) << "cell " << i;
          ++tally.OnChecked;
        }
      }
    }
    // Every point of S in the cell covered; points off S counted.
    for (std::size_t leaf = 0; leaf < leaves.size(); ++leaf)
    {
      for (const tpc::ConvexPolygon& q : tpc::SurfaceInCell(leaves[leaf], scene.Primitives, cell))
      {
        for (int s = 0; s < 20 && q.Points.size() >= 3 && q.TwiceArea > 1e-12; ++s)
        {
          double a = unit(random), b = unit(random);
          if (a + b > 1)
          {
            a = 1 - a;
            b = 1 - b;
          }
          const std::size_t k = 1 + static_cast<std::size_t>(unit(random) * (q.Points.size() - 2)) % (q.Points.size() - 2);
          const Vec3 x = q.Points[0] * (1 - a - b) + q.Points[k] * a + q.Points[k + 1] * b;
          if (!awayFromTheOthers(leaf, x))
          {
            continue;
          }
          if (OnSurfaceByBruteForce(scene, x, q.Normal))
          {
            EXPECT_LE(SetDistance(surface.Covering, x), 1e-12) << "cell " << i;
            ++tally.CoveredChecked;
          }
          else
          {
            EXPECT_GT(SetDistance(surface.OnSurface, x), 0.0) << "cell " << i;
            tally.OffSurfaceLeftOut += SetDistance(surface.Covering, x) > 0.0 ? 1 : 0;
          }
        }
      }
    }
    // The creases lie on two meshes each.
    for (const tpc::CreaseSegment& c : creases)
    {
      for (const Vec3& x : { c.A, c.B, (c.A + c.B) * 0.5 })
      {
        int on = 0;
        for (std::size_t leaf = 0; leaf < leaves.size(); ++leaf)
        {
          on += MeshDistance(meshOf(leaf), x) <= 1e-12 ? 1 : 0;
        }
        EXPECT_GE(on, 2) << "cell " << i;
      }
      ++tally.Creases;
    }
  }
}
} // namespace

/// Expects every check of CheckEveryCell to have checked something.
void ExpectChecked(const Tally& tally, const std::string& which)
{
  // (Cells where the meshes meet, pieces on S and apart from the other
  // meshes, points of S covered, points off S left out, creases.)
  EXPECT_GE(tally.Cells, 10) << which;
  EXPECT_GE(tally.OnChecked, 100) << which;
  EXPECT_GE(tally.ApartChecked, 1000) << which;
  EXPECT_GE(tally.CoveredChecked, 100) << which;
  EXPECT_GE(tally.OffSurfaceLeftOut, 100) << which;
  EXPECT_GE(tally.Creases, 10) << which;
}

TEST(MeshBooleanSurface, PiecesOnTheSurfaceAndCoveringItAgreeWithBruteForce)
{
  // A tilted icosphere through a tilted box, their surfaces crossing at
  // 20-90 degrees along a closed curve, in every operation; the same sphere
  // barely through the box's face (crossing at a few degrees); and the
  // sphere minus the union of the box and a torus (three meshes).
  const Vec3 axis = tpc::Normalized(Vec3(0.3, 1.0, 0.2));
  const MeshSolid sphere = tpctest::AffineMesh(tpctest::SphereMesh({ 0, 0, 0 }, 0.55, 2), { 1, 1, 1 }, axis, 0.3,
    { 0.31, 0.02, -0.03 });
  const MeshSolid box =
    tpctest::AffineMesh(tpctest::CubeMesh({ -0.4, -0.4, -0.4 }, { 0.4, 0.4, 0.4 }), { 1, 1.3, 0.9 }, axis, 0.7,
      { -0.2, 0.01, 0.02 });
  const MeshSolid grazed = tpctest::AffineMesh(tpctest::CubeMesh({ -0.9, -0.9, -0.9 }, { 0.9, 0.9, 0.37 }),
    { 1, 1, 1 }, { 1, 0, 0 }, 0.03, { 0.31, 0.02, -0.03 });
  const MeshSolid ring = tpctest::AffineMesh(
    tpctest::TorusMesh({ 0, 0, 0 }, 0.5, 0.12, 24, 10), { 1, 1, 1 }, { 0, 1, 0 }, 1.2, { 0.3, 0.0, 0.0 });
  for (const CsgTerm::Op op : { CsgTerm::Op::Union, CsgTerm::Op::Intersection, CsgTerm::Op::Difference })
  {
    tpctest::SceneBuilder builder;
    const CsgTerm a = builder.Mesh(sphere), b = builder.Mesh(box);
    builder.Finish(CsgTerm::Combine(op, { a, b }));
    Tally tally;
    CheckEveryCell(builder.Scene, tally);
    ExpectChecked(tally, "operation " + std::to_string(static_cast<int>(op)));
  }
  {
    tpctest::SceneBuilder builder;
    const CsgTerm a = builder.Mesh(sphere), b = builder.Mesh(grazed);
    builder.Finish(CsgTerm::Combine(CsgTerm::Op::Difference, { a, b }));
    Tally tally;
    CheckEveryCell(builder.Scene, tally);
    ExpectChecked(tally, "grazing");
  }
  {
    tpctest::SceneBuilder builder;
    const CsgTerm a = builder.Mesh(sphere), b = builder.Mesh(box), c = builder.Mesh(ring);
    builder.Finish(tpctest::SceneBuilder::Difference({ a, tpctest::SceneBuilder::Union({ b, c }) }));
    Tally tally;
    CheckEveryCell(builder.Scene, tally);
    ExpectChecked(tally, "three meshes");
  }
}

TEST(MeshBooleanSurface, OnlyExpressionsOfMeshesMeetingAreMeshBooleans)
{
  const MeshSolid cube = tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 });
  const MeshSolid shifted = tpctest::CubeMesh({ -0.3, -0.4, -0.5 }, { 0.7, 0.6, 0.5 });
  tpctest::SceneBuilder builder;
  const CsgTerm a = builder.Mesh(cube), b = builder.Mesh(shifted), sphere = builder.Sphere({ 0, 0, 0 }, 0.6);
  const tpc::PrimitiveSet& primitives = builder.Scene.Primitives;
  // (Pruned to a box, as the cells' expressions are: mesh leaves then list
  // their triangles.)
  const auto meshBoolean = [&](const CsgTerm& t) {
    const auto pruned = tpc::CsgExpression::Prune(tpc::CsgExpression::FromTerm(t), { { -1, -1, -1 }, { 1, 1, 1 } },
      primitives);
    return pruned.Sign == tpc::RegionSign::Mixed && tpc::IsMeshBoolean(*pruned.Expression);
  };
  EXPECT_TRUE(meshBoolean(CsgTerm::Combine(CsgTerm::Op::Union, { a, b })));
  EXPECT_FALSE(meshBoolean(a));
  EXPECT_FALSE(meshBoolean(CsgTerm::Combine(CsgTerm::Op::Difference, { a, sphere })));
  // (A mesh and its own complement: one mesh in two leaves.)
  EXPECT_FALSE(meshBoolean(
    CsgTerm::Combine(CsgTerm::Op::Union, { CsgTerm::Combine(CsgTerm::Op::Difference, { b, a }), a })));
  // (Not pruned: the leaves list no triangles.)
  EXPECT_FALSE(tpc::IsMeshBoolean(*tpc::CsgExpression::FromTerm(CsgTerm::Combine(CsgTerm::Op::Union, { a, b }))));
}

TEST(MeshBooleanSurface, ThePatchIsMeasuredAgainstEachSideInItsDirection)
{
  // S known from two sides: a unit square on it, and the square with a
  // triangle 0.3 above it covering it. The square's patch is on S (h(P, on
  // S) = 0) but the covering triangle is 0.3 from it: the bound must see
  // that, and the sets swapped must not (the triangle would be a target).
  tpc::PolygonSet on, covering;
  on.Add({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } });
  covering.Add({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } });
  covering.Add({ { 0.2, 0.2, 0.3 }, { 0.8, 0.2, 0.3 }, { 0.5, 0.8, 0.3 } });
  const std::vector<tpc::SourceTriangle> patch = { { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0) },
    { Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0) } };
  const tpc::HausdorffEstimate e = tpc::CertifiedSurfacePatchError(on, covering, patch, 0.0, 0.01, 1.0, 4096);
  EXPECT_GE(e.Upper, 0.3);
  EXPECT_LE(e.Upper, 0.33); // (refined to within 10 % of the distance attained)
  const tpc::HausdorffEstimate swapped = tpc::CertifiedSurfacePatchError(covering, on, patch, 0.0, 0.01, 1.0, 4096);
  EXPECT_LE(swapped.Upper, 0.01);
}

TEST(MeshBooleanSurface, PolygonsAreApartOnlyFartherThanTheMargin)
{
  const auto span = [](const std::vector<Vec3>& p) { return PointSpan{ p.data(), p.size() }; };
  // Parallel triangles 0.01 apart.
  const std::vector<Vec3> low = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  const std::vector<Vec3> high = { { 0, 0, 0.01 }, { 1, 0, 0.01 }, { 0, 1, 0.01 } };
  EXPECT_TRUE(tpc::PolygonsApart(span(low), span(high), 0.009));
  EXPECT_FALSE(tpc::PolygonsApart(span(low), span(high), 0.011));
  // Crossing triangles: never.
  const std::vector<Vec3> standing = { { 0.2, 0.2, -0.5 }, { 0.3, 0.2, 0.5 }, { 0.2, 0.3, 0.5 } };
  EXPECT_FALSE(tpc::PolygonsApart(span(low), span(standing), 0.0));
  // Two triangles whose nearest points are on two skew edges, turned so
  // that only the edges' cross product separates them: 0.02 apart.
  const Vec3 axis = tpc::Normalized(Vec3(0.4, -0.7, 0.5));
  const auto turned = [&](std::vector<Vec3> p) {
    for (Vec3& x : p)
    {
      x = x * std::cos(0.9) + tpc::Cross(axis, x) * std::sin(0.9) + axis * (tpc::Dot(axis, x) * (1 - std::cos(0.9)));
    }
    return p;
  };
  const std::vector<Vec3> a = turned({ { -1, 0, 0 }, { 1, 0, 0 }, { 0, 0, -1 } });
  const std::vector<Vec3> b = turned({ { 0, -1, 0.02 }, { 0, 1, 0.02 }, { 0, 0, 1.02 } });
  EXPECT_TRUE(tpc::PolygonsApart(span(a), span(b), 0.019));
  EXPECT_FALSE(tpc::PolygonsApart(span(a), span(b), 0.021));
}

TEST(MeshBooleanSurface, PolygonsCrossingAPlaneAreApartOnlyOutsideThePolygonInIt)
{
  // A triangle standing across another's plane, a distance r beyond one of
  // its sides (the side's outward direction in the plane separates them by
  // r) or r within it (they cross): apart by a margin below r in the first
  // case, never in the second - crossing polygons are told by where the
  // standing one's section lies (PolygonsApartBesideTheirBoxes), which must
  // not be taken for a crossing outside.
  const auto span = [](const std::vector<Vec3>& p) { return PointSpan{ p.data(), p.size() }; };
  std::uint64_t state = 2024;
  const auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  int apart = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    // An equilateral triangle of side 0.6 (inradius 0.17, so a point 0.03
    // inside a side's midpoint is well inside it), turned and moved at
    // random.
    const Vec3 axis = tpc::Normalized(Vec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5));
    const double angle = 6.0 * uniform(), c = std::cos(angle), s = std::sin(angle);
    const Vec3 shift(uniform(), uniform(), uniform());
    tpc::PolygonSet set;
    std::vector<Vec3> q;
    for (int k = 0; k < 3; ++k)
    {
      const double at = 2.0 * M_PI / 3.0 * k;
      const Vec3 corner(0.6 / std::sqrt(3.0) * std::cos(at), 0.6 / std::sqrt(3.0) * std::sin(at), 0.0);
      q.push_back(corner * c + tpc::Cross(axis, corner) * s + axis * (tpc::Dot(axis, corner) * (1 - c)) + shift);
    }
    set.Add(q.data(), q.size());
    ASSERT_FALSE(set[0].Inward.empty());
    const Vec3 n = set[0].Normal;
    const int side = trial % 3;
    const Vec3 e = tpc::Normalized(q[(side + 1) % 3] - q[side]);
    const Vec3 outward = tpc::Cross(e, n); // (in the plane, away from the third corner: counter-clockwise about n)
    ASSERT_LT(tpc::Dot(outward, q[(side + 2) % 3] - q[side]), 0.0);
    const Vec3 middle = (q[side] + q[(side + 1) % 3]) * 0.5;
    const double r = 0.01 + 0.02 * uniform();
    for (const double sign : { 1.0, -1.0 })
    {
      const Vec3 x = middle + outward * (sign * r);
      // (Its own plane holds n and the outward direction - neither normal
      // separates them; its section by q's plane runs from x further out,
      // or further in.)
      const std::vector<Vec3> standing = { x - n * 0.3, x + n * 0.3, x + n * 0.1 + outward * (sign * 0.05) };
      const bool found = tpc::PolygonsApartBesideTheirBoxes(span(standing), set[0], 0.8 * r);
      EXPECT_EQ(found, sign > 0.0) << "trial " << trial;
      EXPECT_EQ(tpc::PolygonsApart(span(standing), span(q), 0.8 * r), found) << "trial " << trial;
      apart += found ? 1 : 0;
    }
  }
  EXPECT_EQ(apart, 300);
}
