// S in a cell where meshes meet, bounded from both sides
// (MeshBooleanSurface.h), against brute force: every piece said to be on S
// is (the solid's sign changes across it), every point of S in the cell
// lies on a covering piece while points of the meshes off S (one mesh
// inside the other solid) are left out, and the crease segments lie on both
// meshes; the separating-axis test proves apart only polygons farther apart
// than the margin asked.
#include "MeshBooleanSurface.h"
#include "MeshBuilders.h"
#include "MeshCellError.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

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

struct Tally
{
  int Cells = 0, OnChecked = 0, CoveredChecked = 0, OffSurfaceLeftOut = 0, Creases = 0;
};

/// Checks S's two sides in every cell of a 8^3 grid over [-1, 1]^3 where
/// the scene's two meshes meet (header), points within `away` of the other
/// mesh left unchecked (the brute-force sign test needs room).
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
    ASSERT_EQ(leaves.size(), 2u);
    const auto awayFromTheOther = [&](std::size_t leaf, const Vec3& x) {
      return MeshDistance(scene.Primitives.Meshes[leaves[1 - leaf].Primitive], x) > Away;
    };
    const auto leafOf = [&](const Vec3& x) {
      return MeshDistance(scene.Primitives.Meshes[leaves[0].Primitive], x) <
          MeshDistance(scene.Primitives.Meshes[leaves[1].Primitive], x)
        ? 0
        : 1;
    };
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
        if (q.TwiceArea > 1e-12 && awayFromTheOther(leafOf(x), x))
        {
          EXPECT_TRUE(OnSurfaceByBruteForce(scene, x, q.Normal)) << "cell " << i;
          ++tally.OnChecked;
        }
      }
    }
    // Every point of S in the cell covered; points off S counted.
    for (std::size_t leaf = 0; leaf < 2; ++leaf)
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
          if (!awayFromTheOther(leaf, x))
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
    // The creases lie on both meshes.
    for (const tpc::CreaseSegment& c : creases)
    {
      for (const Vec3& x : { c.A, c.B, (c.A + c.B) * 0.5 })
      {
        EXPECT_LE(MeshDistance(scene.Primitives.Meshes[leaves[0].Primitive], x), 1e-12);
        EXPECT_LE(MeshDistance(scene.Primitives.Meshes[leaves[1].Primitive], x), 1e-12);
      }
      ++tally.Creases;
    }
  }
}
} // namespace

TEST(MeshBooleanSurface, PiecesOnTheSurfaceAndCoveringItAgreeWithBruteForce)
{
  // A tilted icosphere through a tilted box: their surfaces cross at 20-90
  // degrees along a closed curve.
  const Vec3 axis = tpc::Normalized(Vec3(0.3, 1.0, 0.2));
  const MeshSolid sphere = tpctest::AffineMesh(tpctest::SphereMesh({ 0, 0, 0 }, 0.55, 2), { 1, 1, 1 }, axis, 0.3,
    { 0.31, 0.02, -0.03 });
  const MeshSolid box =
    tpctest::AffineMesh(tpctest::CubeMesh({ -0.4, -0.4, -0.4 }, { 0.4, 0.4, 0.4 }), { 1, 1.3, 0.9 }, axis, 0.7,
      { -0.2, 0.01, 0.02 });
  for (const CsgTerm::Op op : { CsgTerm::Op::Union, CsgTerm::Op::Intersection, CsgTerm::Op::Difference })
  {
    tpctest::SceneBuilder builder;
    const CsgTerm a = builder.Mesh(sphere), b = builder.Mesh(box);
    builder.Finish(CsgTerm::Combine(op, { a, b }));
    Tally tally;
    CheckEveryCell(builder.Scene, tally);
    const std::string which = "operation " + std::to_string(static_cast<int>(op));
    // (So that the checks above checked something: cells where the meshes
    // meet, pieces on S, points of S covered, points off S left out, and
    // creases.)
    EXPECT_GE(tally.Cells, 10) << which;
    EXPECT_GE(tally.OnChecked, 100) << which;
    EXPECT_GE(tally.CoveredChecked, 100) << which;
    EXPECT_GE(tally.OffSurfaceLeftOut, 100) << which;
    EXPECT_GE(tally.Creases, 10) << which;
  }
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
