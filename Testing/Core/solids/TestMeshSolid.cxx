// Meshes as solids: exact inside/outside even for queries that hit edges and
// vertices, crossing counts consistent with it, conservative triangle/box
// overlap, and the whole pipeline on meshes and mesh/quadric CSG.
#include "CoreContour.h"
#include "ExactPredicates.h"
#include "ExactSum.h"
#include "MeshBuilders.h"
#include "SceneBuilder.h"
#include "SurfaceExtraction.h"
#include "TopologyReport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using tpc::Box3;
using tpc::Vec3;
using tpctest::SceneBuilder;

TEST(ExactPredicates, AgreeWithIntegerArithmetic)
{
  // Small integer coordinates: the determinants are exact in 64-bit integers.
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> c(-3, 3);
  int zeros = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const long long a[3] = { c(rng), c(rng), c(rng) }, b[3] = { c(rng), c(rng), c(rng) },
                    d[3] = { c(rng), c(rng), c(rng) }, e[3] = { c(rng), c(rng), c(rng) };
    const long long ad[3] = { a[0] - e[0], a[1] - e[1], a[2] - e[2] };
    const long long bd[3] = { b[0] - e[0], b[1] - e[1], b[2] - e[2] };
    const long long cd[3] = { d[0] - e[0], d[1] - e[1], d[2] - e[2] };
    const long long det = ad[0] * (bd[1] * cd[2] - bd[2] * cd[1]) - ad[1] * (bd[0] * cd[2] - bd[2] * cd[0]) +
      ad[2] * (bd[0] * cd[1] - bd[1] * cd[0]);
    const int expected = det > 0 ? 1 : (det < 0 ? -1 : 0);
    // Scaling by a power of two keeps the coordinates exact, and the sign.
    for (const double f : { 1.0, 0.125, 1024.0 })
    {
      ASSERT_EQ(tpc::Orient3D(Vec3(a[0] * f, a[1] * f, a[2] * f), Vec3(b[0] * f, b[1] * f, b[2] * f),
                  Vec3(d[0] * f, d[1] * f, d[2] * f), Vec3(e[0] * f, e[1] * f, e[2] * f)),
        expected);
    }
    const long long o2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    ASSERT_EQ(tpc::Orient2D(a[0], a[1], b[0], b[1], d[0], d[1]), o2 > 0 ? 1 : (o2 < 0 ? -1 : 0));
    zeros += expected == 0 ? 1 : 0;
  }
  EXPECT_GT(zeros, 100); // degenerate cases were exercised
}

TEST(ExactPredicates, NearlyDegenerateCasesPastTheFloatingPointFilter)
{
  // Shewchuk's example: a point a hair off the line through (12, 12) and
  // (24, 24), on a grid of ulps around (0.5, 0.5), where plain floating point
  // gets signs wrong. Exact reference: every coordinate is an integer
  // multiple of 2^-53, so the determinant is exact in 128-bit integers.
  const double ulp = std::ldexp(1.0, -53);
  const auto units = [ulp](double x) { return static_cast<__int128>(x / ulp); };
  int positives = 0, negatives = 0, zeros = 0;
  for (int i = 0; i < 64; ++i)
  {
    for (int j = 0; j < 64; ++j)
    {
      const double ax = 0.5 + i * ulp, ay = 0.5 + j * ulp;
      const __int128 exact =
        (units(12.0) - units(ax)) * (units(24.0) - units(ay)) - (units(12.0) - units(ay)) * (units(24.0) - units(ax));
      const int expected = exact > 0 ? 1 : (exact < 0 ? -1 : 0);
      ASSERT_EQ(tpc::Orient2D(ax, ay, 12.0, 12.0, 24.0, 24.0), expected) << i << " " << j;
      // The same determinant as a 3-D one: a, b, c in z = 0, d above them.
      ASSERT_EQ(tpc::Orient3D(Vec3(12.0, 12.0, 0.0), Vec3(24.0, 24.0, 0.0), Vec3(ax, ay, 1.0), Vec3(ax, ay, 0.0)),
        expected)
        << i << " " << j;
      positives += expected > 0;
      negatives += expected < 0;
      zeros += expected == 0;
    }
  }
  EXPECT_GT(positives, 0);
  EXPECT_GT(negatives, 0);
  EXPECT_GT(zeros, 0);
}

TEST(ExactPredicates, Orient3DExactWhereDifferencesRound)
{
  // a, b, d on the plane x = y and c off it by an ulp or on it: the
  // determinant is (c.x - c.y) (p s - q r) exactly, with p, q, r, s the x and
  // z differences of a and b from d, so its sign is known. Random coordinates
  // of mixed magnitudes make the differences round (the exact stage carries
  // their rounding errors; dropping them gets these signs wrong).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-30, 30);
  int checked = 0, zeros = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const auto coordinate = [&] { return std::ldexp(unit(rng), scale(rng)); };
    const double ax = coordinate(), bx = coordinate(), dx = coordinate();
    const Vec3 a(ax, ax, coordinate()), b(bx, bx, coordinate()), d(dx, dx, coordinate());
    const double p = a[0] - d[0], q = a[2] - d[2], r = b[0] - d[0], s = b[2] - d[2];
    const double ps = p * s, qr = q * r;
    if (!(std::fabs(ps - qr) > 1e-6 * (std::fabs(ps) + std::fabs(qr))))
    {
      continue; // (the second factor's sign not certain in floating point)
    }
    const double cx = coordinate();
    const int offset = trial % 3 - 1; // c.y one ulp below c.x, equal, or above
    const double cy = offset == 0 ? cx : std::nextafter(cx, offset > 0 ? HUGE_VAL : -HUGE_VAL);
    const int expected = (cx > cy ? 1 : cx < cy ? -1 : 0) * (ps - qr > 0.0 ? 1 : -1);
    ASSERT_EQ(tpc::Orient3D(a, b, Vec3(cx, cy, coordinate()), d), expected) << trial;
    ++checked;
    zeros += expected == 0 ? 1 : 0;
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(zeros, 3000);
}

namespace
{
/// The sign of det[a - d, b - d, c - d] from the 48 products of raw
/// coordinates (each difference x - y expanded into x and -y), summed
/// exactly: an exact reference independent of how Orient3D splits the
/// differences.
int CoordinateExpansionSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3* rows[3] = { &a, &b, &c };
  static const int perms[6][3] = { { 0, 1, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 0, 2, 1 }, { 2, 1, 0 }, { 1, 0, 2 } };
  static const int parity[6] = { 1, 1, 1, -1, -1, -1 };
  tpc::ExactSum sum;
  for (int p = 0; p < 6; ++p)
  {
    for (int choice = 0; choice < 8; ++choice)
    {
      double f[3];
      for (int r = 0; r < 3; ++r)
      {
        const int column = perms[p][r];
        f[r] = (choice >> r) & 1 ? -d[column] : (*rows[r])[column];
      }
      sum.AddProduct(parity[p] * f[0], f[1], f[2]);
    }
  }
  return sum.Sign();
}
} // namespace

TEST(ExactPredicates, Orient3DAgreesWithTheCoordinateExpansionNearCoplanarPoints)
{
  // d in the plane of a, b, c up to rounding, then moved by a few ulps:
  // determinants far below the filters' reach, with differences that round
  // (coordinates of mixed magnitudes), so that products of one, two and three
  // rounding errors all take part in the exact sum.
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-8, 8), nudge(-2, 2), axis(0, 2);
  int signs[3] = { 0, 0, 0 };
  for (int trial = 0; trial < 20000; ++trial)
  {
    const auto coordinate = [&] { return std::ldexp(unit(rng), scale(rng)); };
    const Vec3 a(coordinate(), coordinate(), coordinate()), b(coordinate(), coordinate(), coordinate()),
      c(coordinate(), coordinate(), coordinate());
    const double s = unit(rng), t = unit(rng);
    Vec3 d = a + (b - a) * s + (c - a) * t;
    const int k = axis(rng);
    for (int step = nudge(rng); step != 0; step += step > 0 ? -1 : 1)
    {
      d[k] = std::nextafter(d[k], step > 0 ? HUGE_VAL : -HUGE_VAL);
    }
    const int expected = CoordinateExpansionSign(a, b, c, d);
    ASSERT_EQ(tpc::Orient3D(a, b, c, d), expected) << trial;
    ++signs[expected + 1];
  }
  EXPECT_GT(signs[0], 1000);
  EXPECT_GT(signs[2], 1000);
}

TEST(MeshSolid, InsideIsExactOnQueriesThroughEdgesAndVertices)
{
  // A cube mesh queried on a lattice that contains its vertices: rays hit
  // edges and vertices all the time.
  const tpc::MeshSolid cube = tpctest::CubeMesh({ -1, -1, -1 }, { 1, 1, 1 });
  int inside = 0;
  for (int i = -4; i <= 4; ++i)
  {
    for (int j = -4; j <= 4; ++j)
    {
      for (int k = -4; k <= 4; ++k)
      {
        const Vec3 p(0.5 * i, 0.5 * j, 0.5 * k);
        // Off the surface: the cube. On it: as just beside p along (+, +, +)
        // (the shared symbolic perturbation), i.e. inside iff each
        // coordinate is in [-1, 1).
        const bool expected = i >= -2 && i < 2 && j >= -2 && j < 2 && k >= -2 && k < 2;
        ASSERT_EQ(cube.IsInside(p), expected) << i << " " << j << " " << k;
        inside += expected ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(inside, 64);
}

TEST(MeshSolid, InsideMatchesTheAnalyticTorusAwayFromTheSurface)
{
  const double R = 0.6, r = 0.25;
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, R, r, 64, 32);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const Vec3 p(u(rng), u(rng), 0.5 * u(rng));
    const double q = std::hypot(std::hypot(p[0], p[1]) - R, p[2]) - r;
    if (std::fabs(q) < 0.01) // the facetted mesh differs from the torus there
    {
      continue;
    }
    ASSERT_EQ(torus.IsInside(p), q < 0) << p[0] << " " << p[1] << " " << p[2];
    ++checked;
  }
  EXPECT_GT(checked, 15000);
}

TEST(MeshSolid, RaysEitherWayAlongXAgreeOnInside)
{
  // IsInside casts its ray to the nearer side of the box; the crossings
  // each way must have the same parity at every point - at the vertices,
  // on the edges and faces of the meshes too, where the perturbation
  // decides.
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, 0.6, 0.25, 24, 12);
  const tpc::MeshSolid cube = tpctest::TiltedMesh(tpctest::CubeMesh({ -0.5, -0.5, -0.5 }, { 0.5, 0.5, 0.5 }));
  const tpc::MeshSolid lattice = tpctest::CubeMesh({ -1, -1, -1 }, { 1, 1, 1 });
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  const auto all = [](std::uint32_t) { return true; };
  int inside = 0, checked = 0;
  for (const tpc::MeshSolid* mesh : { &torus, &cube, &lattice })
  {
    std::vector<Vec3> queries;
    for (std::uint32_t t = 0; t < mesh->TriangleCount(); ++t)
    {
      const Vec3 &a = mesh->Vertex(t, 0), &b = mesh->Vertex(t, 1), &c = mesh->Vertex(t, 2);
      queries.insert(queries.end(), { a, (a + b) * 0.5, (a + b + c) * (1.0 / 3.0), a + Vec3(0.25, 0, 0) });
    }
    for (int k = 0; k < 2000; ++k)
    {
      queries.emplace_back(u(rng), u(rng), u(rng));
    }
    for (int i = -5; i <= 5; ++i)
    {
      for (int j = -5; j <= 5; ++j)
      {
        queries.emplace_back(0.25 * i, 0.25 * j, 0.5);
      }
    }
    for (const Vec3& p : queries)
    {
      const int forward = mesh->CrossingsAlongX(p, all, false), backward = mesh->CrossingsAlongX(p, all, true);
      ASSERT_EQ(forward % 2, backward % 2) << p[0] << " " << p[1] << " " << p[2];
      ASSERT_EQ(mesh->IsInside(p), forward % 2 == 1);
      inside += forward % 2;
      ++checked;
    }
  }
  EXPECT_GT(inside, 500);
  EXPECT_GT(checked - inside, 500);
}

TEST(MeshSolid, CrossingCountsAgreeWithInsideChanges)
{
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0, 0, 0 }, 0.6, 0.25, 24, 12);
  const tpc::TriangleList all = torus.Overlapping(torus.Bounds());
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> lattice(-16, 16);
  for (int trial = 0; trial < 3000; ++trial)
  {
    // Segments on a coarse lattice so that some pass through mesh vertices.
    const int axis = trial % 3;
    Vec3 a(lattice(rng) / 16.0, lattice(rng) / 16.0, lattice(rng) / 32.0);
    Vec3 b = a;
    b[axis] += (1 + trial % 7) / 8.0;
    const int n = torus.CountCrossings(a, b, axis, all);
    ASSERT_EQ(n % 2 == 1, torus.IsInside(a) != torus.IsInside(b)) << "trial " << trial;
  }
}

TEST(MeshSolid, TriangleBoxOverlapNeverMissesAContact)
{
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0, 0, 0 }, 0.7, 2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0), s(0.01, 0.3);
  int positives = 0, negatives = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    Box3 box;
    const double size = s(rng);
    for (int a = 0; a < 3; ++a)
    {
      box.lo[a] = u(rng);
      box.hi[a] = box.lo[a] + size;
    }
    const tpc::TriangleList hit = sphere.Overlapping(box);
    for (std::uint32_t t = 0; t < sphere.TriangleCount(); ++t)
    {
      // Brute force: dense samples of the triangle inside the box.
      bool touches = false;
      for (int i = 0; i <= 12 && !touches; ++i)
      {
        for (int j = 0; i + j <= 12 && !touches; ++j)
        {
          const Vec3 p = sphere.Vertex(t, 0) * ((12.0 - i - j) / 12.0) + sphere.Vertex(t, 1) * (i / 12.0) +
            sphere.Vertex(t, 2) * (j / 12.0);
          touches = box.Contains(p);
        }
      }
      const bool reported = std::find(hit.begin(), hit.end(), t) != hit.end();
      if (touches)
      {
        ASSERT_TRUE(reported) << "triangle " << t << " trial " << trial;
      }
      positives += touches ? 1 : 0;
      negatives += !reported ? 1 : 0;
    }
  }
  EXPECT_GT(positives, 100);
  EXPECT_GT(negatives, 100000); // and it does reject
}

TEST(MeshSolid, ATriangleWhoseSidePassesBesideABoxIsNotListed)
{
  // The plane x + z = 2 + d passes the unit box's edge (x = z = 1) at d /
  // sqrt(2); a triangle in it, corners outside the box and a side passing
  // its edge, meets the box exactly when d <= 0 - the side's own test must
  // not list it otherwise (only the plane's axis separates it).
  const Box3 box{ { 0, 0, 0 }, { 1, 1, 1 } };
  for (const double d : { 1e-6, 1e-3, -1e-6, -1e-3 })
  {
    const tpc::MeshSolid triangle(
      { { 2 + d, -1, 0 }, { 2 + d, 2, 0 }, { 0, 0.5, 2 + d } }, { { { 0, 1, 2 } } });
    tpc::TriangleList listed;
    triangle.Overlapping(box, tpc::TriangleList{ 0 }, listed);
    EXPECT_EQ(listed.size(), d < 0 ? 1u : 0u) << d;
  }
}

TEST(MeshSolid, ABoxFarBeyondTheMeshListsEveryTriangle)
{
  // The ray-casting grid's columns under a box billions of steps wide: the
  // column of its far side once overflowed the int conversion to the first
  // column, so a box around the whole mesh listed no triangle - and a run
  // whose Bounds were that large took its root cell as empty and returned
  // an empty surface, guaranteed (GridIndex.h).
  const tpc::MeshSolid torus = tpctest::TorusMesh({ 0.013, -0.007, 0.004 }, 1.0, 0.35, 96, 48);
  for (const double b : { 1e3, 1e8, 1e12, 1e300 })
  {
    EXPECT_EQ(torus.Overlapping(tpc::Box3{ { -b, -b, -b }, { b, b, b } }).size(), torus.TriangleCount()) << b;
  }
  for (const double b : { 1e8, 1e9 })
  {
    tpctest::SceneBuilder s;
    s.Finish(s.Mesh(torus));
    tpc::ContourParameters p;
    p.Bounds = tpc::Box3{ { -b, -b, -b }, { b, b, b } };
    p.ToleranceIsRelative = false;
    p.Tolerance = 0.05;
    const tpc::ContourResult r = tpc::Contour(tpctest::ContourSceneOf(s.Scene), p);
    EXPECT_TRUE(r.Report.Guaranteed) << b;
    EXPECT_EQ(r.Topology.Components, 1) << b;
    EXPECT_EQ(r.Topology.Genus, 1) << b;
    EXPECT_GT(r.Extraction.Mesh.Triangles.size(), 100u) << b;
  }
}

TEST(MeshSolid, KnowsEachEdgesOtherTriangleAndEachUnitNormal)
{
  // Brute force: the other triangle holding both ends of each edge, and the
  // normalized cross product of the edges; on a closed sphere every edge has
  // one, symmetric; cut open (half its triangles), the cut's edges have none.
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0.1, -0.2, 0.3 }, 0.7, 2);
  const auto holds = [](const std::array<std::uint32_t, 3>& ids, std::uint32_t v) {
    return ids[0] == v || ids[1] == v || ids[2] == v;
  };
  const auto otherOf = [&](const tpc::MeshSolid& mesh, std::uint32_t t, int k) {
    const std::uint32_t a = mesh.Triangles()[t][k], b = mesh.Triangles()[t][(k + 1) % 3];
    std::uint32_t found = tpc::MeshSolid::NoTriangle;
    int count = 0;
    for (std::uint32_t u = 0; u < mesh.TriangleCount(); ++u)
    {
      if (u != t && holds(mesh.Triangles()[u], a) && holds(mesh.Triangles()[u], b))
      {
        found = u;
        ++count;
      }
    }
    return count == 1 ? found : tpc::MeshSolid::NoTriangle;
  };
  for (std::uint32_t t = 0; t < sphere.TriangleCount(); ++t)
  {
    const Vec3 n = tpc::Cross(sphere.Vertex(t, 1) - sphere.Vertex(t, 0), sphere.Vertex(t, 2) - sphere.Vertex(t, 0));
    EXPECT_NEAR(tpc::Dot(sphere.Normal(t), n * (1.0 / tpc::Norm(n))), 1.0, 1e-12) << "triangle " << t;
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t other = sphere.Across(t, k);
      ASSERT_NE(other, tpc::MeshSolid::NoTriangle) << "triangle " << t << " edge " << k;
      EXPECT_EQ(other, otherOf(sphere, t, k));
      const auto& back = sphere.Triangles()[other];
      EXPECT_TRUE(sphere.Across(other, 0) == t || sphere.Across(other, 1) == t || sphere.Across(other, 2) == t);
      EXPECT_TRUE(holds(back, sphere.Triangles()[t][k]) && holds(back, sphere.Triangles()[t][(k + 1) % 3]));
    }
  }
  std::vector<std::array<std::uint32_t, 3>> half(
    sphere.Triangles().begin(), sphere.Triangles().begin() + sphere.TriangleCount() / 2);
  const tpc::MeshSolid open(sphere.Points(), half);
  int cut = 0;
  for (std::uint32_t t = 0; t < open.TriangleCount(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(open.Across(t, k), otherOf(open, t, k)) << "triangle " << t << " edge " << k;
      cut += open.Across(t, k) == tpc::MeshSolid::NoTriangle ? 1 : 0;
    }
  }
  EXPECT_GT(cut, 4); // the cut was exercised
}

namespace
{
/// Largest distance from a point of `points` to the mesh (brute force).
double FarthestFromMesh(const std::vector<Vec3>& points, const tpc::MeshSolid& mesh)
{
  tpc::TriangleList all(mesh.TriangleCount());
  for (std::uint32_t t = 0; t < all.size(); ++t)
  {
    all[t] = t;
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); i += 3)
  {
    worst = std::max(worst, std::fabs(mesh.ApproximateSignedDistance(points[i], all)));
  }
  return worst;
}

void ExpectClosedManifold(const tpctest::ContourRun& r)
{
  EXPECT_EQ(r.Subdivision.UnresolvedCells, 0u);
  EXPECT_EQ(r.Extraction.InconsistentCells, 0u);
  EXPECT_TRUE(r.Report.Closed);
  EXPECT_TRUE(r.Report.Manifold);
  EXPECT_TRUE(r.Report.Oriented);
  EXPECT_GT(r.Report.SignedVolume, 0.0);
}
} // namespace

TEST(MeshPipeline, RemeshedTorusKeepsItsTopologyWithinTolerance)
{
  for (const double tolerance : { 0.04, 0.02 })
  {
    SceneBuilder b;
    const tpc::MeshSolid torus = tpctest::TorusMesh({ 0.01, 0.02, 0.03 }, 0.6, 0.25, 48, 24);
    b.Finish(b.Mesh(torus));
    const tpctest::ContourRun r = tpctest::Contour(b.Scene, torus.Bounds(), tolerance);
    ExpectClosedManifold(r);
    EXPECT_EQ(r.Report.Components, 1);
    EXPECT_EQ(r.Report.Genus, 1);
    // One side of the Hausdorff distance: output vertices near the mesh.
    EXPECT_LE(FarthestFromMesh(r.Extraction.Mesh.Points.ToVector(), torus), r.Tolerance);
  }
}

TEST(MeshPipeline, MeshMinusQuadricCylinderHasGenusOne)
{
  SceneBuilder b;
  b.Finish(SceneBuilder::Difference({ b.Mesh(tpctest::SphereMesh({ 0, 0, 0 }, 0.7, 3)),
    b.Cylinder({ 0.05, 0.02, 0 }, { 0.1, 0.2, 1.0 }, 0.2) }));
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, { { -0.7, -0.7, -0.7 }, { 0.7, 0.7, 0.7 } }, 0.03);
  ExpectClosedManifold(r);
  EXPECT_EQ(r.Report.Components, 1);
  EXPECT_EQ(r.Report.Genus, 1);
}

TEST(MeshPipeline, BooleansOfMeshes)
{
  // Two overlapping sphere meshes: one component.
  SceneBuilder u;
  u.Finish(SceneBuilder::Union({ u.Mesh(tpctest::SphereMesh({ -0.3, 0, 0 }, 0.5, 3)),
    u.Mesh(tpctest::SphereMesh({ 0.3, 0.05, 0 }, 0.45, 3)) }));
  const tpctest::ContourRun ru = tpctest::Contour(u.Scene, { { -0.8, -0.5, -0.5 }, { 0.75, 0.5, 0.5 } }, 0.03);
  ExpectClosedManifold(ru);
  EXPECT_EQ(ru.Report.Components, 1);
  EXPECT_EQ(ru.Report.Genus, 0);

  // A slab minus a box through it: a hole, genus 1 (coplanar-free faces).
  SceneBuilder d;
  d.Finish(SceneBuilder::Difference({ d.Mesh(tpctest::CubeMesh({ -0.5, -0.5, -0.2 }, { 0.5, 0.5, 0.2 })),
    d.Mesh(tpctest::CubeMesh({ -0.15, -0.1, -0.3 }, { 0.12, 0.1, 0.3 })) }));
  const tpctest::ContourRun rd = tpctest::Contour(d.Scene, { { -0.5, -0.5, -0.2 }, { 0.5, 0.5, 0.2 } }, 0.03);
  ExpectClosedManifold(rd);
  EXPECT_EQ(rd.Report.Components, 1);
  EXPECT_EQ(rd.Report.Genus, 1);
}
