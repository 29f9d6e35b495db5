// Input polygons as triangles (PolygonTriangulation.h): every polygon of n
// corners gives n - 2 triangles using each of its edges once and each
// diagonal once in each direction, none degenerate, tiling its projection;
// folded polygons are fanned.
#include "ExactPredicates.h"
#include "PolygonTriangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <utility>

using tpc::Vec3;

namespace
{
/// Twice the signed area of triangle (a, b, c) in the plane (u, v).
double Area2(const Vec3& a, const Vec3& b, const Vec3& c, int u, int v)
{
  return (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
}

/// What makes `triangles` a triangulation of the polygon 0, 1, ..., n - 1
/// (n - 2 triangles, the polygon's edges used once each in its direction,
/// other edges - diagonals - once in each direction), and none of them
/// degenerate or turned over in the projection (u, v), where the polygon
/// turns counter-clockwise. Their areas sum to the polygon's.
void ExpectTriangulation(const std::vector<Vec3>& p, const std::vector<tpc::Triangle>& triangles, int u, int v)
{
  const std::uint32_t n = static_cast<std::uint32_t>(p.size());
  ASSERT_EQ(triangles.size(), n - 2u);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  double sum = 0.0, polygon = 0.0;
  for (const tpc::Triangle& t : triangles)
  {
    EXPECT_EQ(tpc::Orient2D(p[t[0]][u], p[t[0]][v], p[t[1]][u], p[t[1]][v], p[t[2]][u], p[t[2]][v]), 1)
      << "a degenerate or turned-over triangle " << t[0] << " " << t[1] << " " << t[2];
    sum += Area2(p[t[0]], p[t[1]], p[t[2]], u, v);
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  auto uses = [&](std::uint32_t a, std::uint32_t b) {
    const auto found = directed.find({ a, b });
    return found == directed.end() ? 0 : found->second;
  };
  for (std::uint32_t i = 0; i < n; ++i)
  {
    polygon += Area2(p[0], p[i], p[(i + 1) % n], u, v);
    EXPECT_EQ(uses(i, (i + 1) % n), 1) << "edge " << i;
    EXPECT_EQ(uses((i + 1) % n, i), 0) << "edge " << i << " reversed";
  }
  for (const auto& [edge, count] : directed)
  {
    if (edge.second != (edge.first + 1) % n && edge.first != (edge.second + 1) % n)
    {
      EXPECT_EQ(count, 1) << "diagonal " << edge.first << " " << edge.second;
      EXPECT_EQ(uses(edge.second, edge.first), 1) << "diagonal " << edge.first << " " << edge.second;
    }
  }
  EXPECT_NEAR(sum, polygon, 1e-12 * std::abs(polygon));
}

std::vector<std::uint32_t> Ids(std::size_t n)
{
  std::vector<std::uint32_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0u);
  return ids;
}

tpc::PolygonTriangulation Triangulate(const std::vector<Vec3>& p, std::vector<tpc::Triangle>& triangles)
{
  const std::vector<std::uint32_t> ids = Ids(p.size());
  return tpc::TriangulatePolygon(p, ids.data(), ids.size(), triangles);
}
} // namespace

TEST(PolygonTriangulation, ANonConvexNearlyPlanarFaceIsClippedIntoEars)
{
  // A comb: five teeth, its corners lifted off the plane by up to 1e-9 (as
  // in a CAD mesh's faces), in the plane z = 0.3 x.
  std::vector<Vec3> p = { { 0, 0, 0 }, { 10, 0, 0 } };
  for (int tooth = 4; tooth >= 0; --tooth) // (counter-clockwise seen from +z)
  {
    p.push_back({ 2.0 * tooth + 2.0, 3.0, 0.0 });
    p.push_back({ 2.0 * tooth + 1.0, 3.0, 0.0 });
    p.push_back({ 2.0 * tooth + 1.0, 1.0, 0.0 });
    p.push_back({ 2.0 * tooth, 1.0, 0.0 });
  }
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    p[i][2] = 0.3 * p[i][0] + (i % 3 == 0 ? 1e-9 : -1e-9);
  }
  std::vector<tpc::Triangle> triangles;
  EXPECT_EQ(Triangulate(p, triangles), tpc::PolygonTriangulation::Ears);
  ExpectTriangulation(p, triangles, 0, 1);
}

TEST(PolygonTriangulation, CollinearCornersGiveNoDegenerateTriangle)
{
  // A square with three corners on each side, a rectangle notch of
  // collinear corners, seen from -z (clockwise from +z).
  std::vector<Vec3> p = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 }, { 4, 0, 0 }, { 4, 1, 0 }, { 4, 2, 0 },
    { 3, 2, 0 }, { 3, 1, 0 }, { 2, 1, 0 }, { 1, 1, 0 }, { 1, 2, 0 }, { 0, 2, 0 }, { 0, 1, 0 } };
  std::reverse(p.begin(), p.end());
  std::vector<tpc::Triangle> triangles;
  EXPECT_EQ(Triangulate(p, triangles), tpc::PolygonTriangulation::Ears);
  ExpectTriangulation(p, triangles, 1, 0); // (counter-clockwise in (y, x))
}

TEST(PolygonTriangulation, AFaceInAWallIsProjectedOnItsOwnPlane)
{
  // An L in the plane x = 2 (its normal along x): dropping z or y would
  // collapse it.
  const std::vector<Vec3> p = { { 2, 0, 0 }, { 2, 2, 0 }, { 2, 2, 1 }, { 2, 1, 1 }, { 2, 1, 2 }, { 2, 0, 2 } };
  std::vector<tpc::Triangle> triangles;
  EXPECT_EQ(Triangulate(p, triangles), tpc::PolygonTriangulation::Ears);
  ExpectTriangulation(p, triangles, 1, 2);
}

TEST(PolygonTriangulation, RandomStarPolygonsAreTriangulatedExactly)
{
  // Star-shaped polygons of 4 to 60 corners with random radii, some corners
  // repeated along an edge's line (collinear), tilted into a random plane
  // and lifted off it by 1e-12.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial)
  {
    const int n = 4 + trial % 57;
    std::vector<Vec3> flat;
    for (int i = 0; i < n; ++i)
    {
      const double angle = 2.0 * M_PI * (i + 0.8 * unit(random)) / n;
      const double radius = 0.2 + unit(random);
      flat.push_back({ radius * std::cos(angle), radius * std::sin(angle), 0.0 });
      if (i > 0 && unit(random) < 0.2) // a corner halfway along the previous edge, exactly
      {
        const Vec3 a = flat[flat.size() - 2], b = flat.back();
        flat.insert(flat.end() - 1, { (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, 0.0 });
      }
    }
    const double tiltX = unit(random) - 0.5, tiltY = unit(random) - 0.5;
    std::vector<Vec3> p;
    for (std::size_t i = 0; i < flat.size(); ++i)
    {
      p.push_back({ flat[i][0], flat[i][1], tiltX * flat[i][0] + tiltY * flat[i][1] + (i % 2 ? 1e-12 : 0.0) });
    }
    std::vector<tpc::Triangle> triangles;
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_EQ(Triangulate(p, triangles), tpc::PolygonTriangulation::Ears);
    ExpectTriangulation(p, triangles, 0, 1);
  }
}

TEST(PolygonTriangulation, AFoldedPolygonIsFannedOnItsEdges)
{
  // A bow tie: its projection crosses itself, so no ear decides it; the fan
  // still uses each of its edges once, so a mesh around it stays closed.
  const std::vector<Vec3> p = { { 0, 0, 0 }, { 2, 2, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { -1, 1, 0 } };
  std::vector<tpc::Triangle> triangles;
  EXPECT_EQ(Triangulate(p, triangles), tpc::PolygonTriangulation::Fan);
  ASSERT_EQ(triangles.size(), 3u);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const tpc::Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  for (std::uint32_t i = 0; i < 5; ++i)
  {
    EXPECT_EQ((directed[{ i, (i + 1) % 5 }]), 1) << "edge " << i;
  }
}

TEST(PolygonTriangulation, ATriangleStaysAsItIs)
{
  const std::vector<Vec3> p = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  std::vector<tpc::Triangle> triangles;
  EXPECT_EQ(Triangulate(p, triangles), tpc::PolygonTriangulation::Ears);
  ASSERT_EQ(triangles.size(), 1u);
  EXPECT_EQ(triangles[0], (tpc::Triangle{ 0, 1, 2 }));
}
