// The extracted surface is embedded (issue 14): no two triangles meet but in
// what they share, no two vertices coincide - on the configurations that
// used to break it (a small solid straddling a cell face, two sheets of a
// thin slab in one cell, thin strokes, a sphere drilled by three cylinders,
// a Menger sponge), at 1/32, 1/64 and 1/128 of the diagonal. Each run is
// checked by the core's exact test and by CGAL's (CoreContour.h), and its
// topology after merging coincident points is compared with the exact one.
#include "CoreContour.h"
#include "MeshBuilders.h"
#include "MeshRepair.h"
#include "SceneBuilder.h"
#include "SurfaceEmbedding.h"

#include <gtest/gtest.h>

#include <map>

using tpc::Box3;
using tpc::Vec3;
using tpctest::SceneBuilder;

namespace
{
const double Tolerances[] = { 1.0 / 32, 1.0 / 64, 1.0 / 128 };

/// The topology of `mesh` once vertices with identical coordinates are one
/// vertex (what writing STL or vtkCleanPolyData does to a surface).
tpc::TopologyReport MergedTopology(const tpc::TriangleMesh& mesh)
{
  std::map<std::array<double, 3>, std::uint32_t> ids;
  tpc::TriangleMesh merged;
  std::vector<std::uint32_t> index(mesh.Points.size());
  for (std::size_t v = 0; v < mesh.Points.size(); ++v)
  {
    const std::array<double, 3> key = { mesh.Points[v][0], mesh.Points[v][1], mesh.Points[v][2] };
    const auto it = ids.emplace(key, static_cast<std::uint32_t>(merged.Points.size())).first;
    if (it->second == merged.Points.size())
    {
      merged.Points.push_back(mesh.Points[v]);
    }
    index[v] = it->second;
  }
  for (const auto& t : mesh.Triangles)
  {
    merged.Triangles.push_back({ index[t[0]], index[t[1]], index[t[2]] });
  }
  return tpc::ComputeTopologyReport(merged);
}

/// Embedded (the core's check; CoreContour.h also holds it against CGAL's),
/// no coincident vertices, the exact topology after merging coincident
/// points, and the guarantee.
void ExpectEmbeddedWithExactTopology(const tpctest::ContourRun& r, long long components, long long genus,
  const std::string& what)
{
  SCOPED_TRACE(what);
  EXPECT_TRUE(r.Embedding.Embedded()) << r.Embedding.ImproperPairs << " improper pairs, "
                                      << r.Embedding.CoincidentVertices << " coincident vertices";
  EXPECT_EQ(tpctest::CgalVerdict(r.Extraction.Mesh).SelfIntersectingPairs, 0u); // (CoreContour.h: also agrees)
  EXPECT_EQ(r.Embedding.CoincidentVertices, 0u);
  const tpc::TopologyReport merged = MergedTopology(r.Extraction.Mesh);
  EXPECT_TRUE(merged.Closed && merged.Manifold);
  EXPECT_EQ(merged.Components, components);
  EXPECT_EQ(merged.Genus, genus);
  EXPECT_TRUE(tpctest::Guaranteed(r));
}

/// Width of the cells the tolerance asks for, and the coordinate of a
/// lattice plane of those cells near `x` on `axis` (the unshifted lattice of
/// an implicit scene, MakeRootGrid).
struct ToleranceCells
{
  double Width = 0.0;
  double PlaneNear(double x, int axis) const
  {
    const double k = std::round((x - Grid.Origin[axis]) / Width);
    return Grid.Origin[axis] + k * Width;
  }
  tpc::RootGrid Grid;
};

ToleranceCells CellsOf(const Box3& bounds, double relativeTolerance)
{
  ToleranceCells c;
  const double tolerance = relativeTolerance * bounds.Diagonal();
  c.Grid = tpc::MakeRootGrid(tpctest::GrownDomain(bounds), tolerance, 16);
  c.Width = std::ldexp(c.Grid.RootSize, -tpc::ToleranceLevel(tpctest::GrownDomain(bounds), tolerance));
  while (c.Width * std::sqrt(3.0) > tolerance * (1 + 1e-9))
  {
    c.Width *= 0.5;
  }
  return c;
}

const Box3 Unit{ { -1, -1, -1 }, { 1, 1, 1 } };
} // namespace

TEST(Embedding, SmallCubeStraddlingACellFace)
{
  // A cube 0.4 cells wide across a face between two cells, at offsets that
  // put its middle on either side of the face or on it: the surface in each
  // cell is a cap over that face. Before, both cells put their fan's centre
  // on the face: two fans over one square with coinciding centres.
  for (const double tolerance : Tolerances)
  {
    const ToleranceCells cells = CellsOf(Unit, tolerance);
    const double w = cells.Width, x0 = cells.PlaneNear(0.3, 0);
    const double y = cells.PlaneNear(0.1, 1) + 0.5 * w, z = cells.PlaneNear(0.1, 2) + 0.45 * w;
    for (const double offset : { -0.15, -0.05, 0.0, 0.05, 0.15 })
    {
      for (const bool beside : { false, true })
      {
        SceneBuilder b;
        const Vec3 c{ x0 + offset * w, y, z }, h{ 0.2 * w, 0.2 * w, 0.2 * w };
        tpc::CsgTerm cube = b.Box(c - h, c + h);
        b.Finish(beside ? SceneBuilder::Union({ cube, b.Sphere({ -0.4, 0, 0 }, 0.5) }) : cube);
        const tpctest::ContourRun r = tpctest::Contour(b.Scene, Unit, tolerance);
        ExpectEmbeddedWithExactTopology(r, beside ? 2 : 1, 0,
          "tolerance " + std::to_string(tolerance) + " offset " + std::to_string(offset) +
            (beside ? " beside a sphere" : ""));
      }
    }
  }
}

TEST(Embedding, SmallMeshCubeStraddlingACellFace)
{
  // The same as a mesh (the lattice is shifted off mesh faces by less than
  // the finest cell: the cube still straddles the face).
  for (const double tolerance : Tolerances)
  {
    const ToleranceCells cells = CellsOf(Unit, tolerance);
    const double w = cells.Width, x0 = cells.PlaneNear(0.3, 0);
    const double y = cells.PlaneNear(0.1, 1) + 0.5 * w, z = cells.PlaneNear(0.1, 2) + 0.45 * w;
    for (const double offset : { -0.1, 0.0, 0.1 })
    {
      SceneBuilder b;
      const Vec3 c{ x0 + offset * w, y, z }, h{ 0.2 * w, 0.2 * w, 0.2 * w };
      b.Finish(SceneBuilder::Union({ b.Mesh(tpctest::CubeMesh(c - h, c + h)), b.Sphere({ -0.4, 0, 0 }, 0.5) }));
      const tpctest::ContourRun r = tpctest::Contour(b.Scene, Unit, tolerance);
      ExpectEmbeddedWithExactTopology(
        r, 2, 0, "tolerance " + std::to_string(tolerance) + " offset " + std::to_string(offset));
    }
  }
}

TEST(Embedding, ThinSlabsAndStrokes)
{
  // Slabs and strokes thinner than a cell: two sheets of the surface in one
  // cell, each loop's patch on its own side. Letters: an "H" (three strokes,
  // one component) and an "i" (a stem and a dot: two).
  for (const double tolerance : Tolerances)
  {
    const ToleranceCells cells = CellsOf(Unit, tolerance);
    const double w = cells.Width, t = 0.3 * w;
    const double z0 = cells.PlaneNear(0.0, 2) + 0.35 * w;
    {
      SceneBuilder b;
      b.Finish(b.Box({ -0.7, -0.6, z0 }, { 0.7, 0.6, z0 + t }));
      ExpectEmbeddedWithExactTopology(tpctest::Contour(b.Scene, Unit, tolerance), 1, 0,
        "slab at tolerance " + std::to_string(tolerance));
    }
    {
      SceneBuilder b;
      const double s = 0.6 * w; // stroke width
      b.Finish(SceneBuilder::Union({ b.Box({ -0.8, -0.6, z0 }, { -0.8 + s, 0.6, z0 + t }),
        b.Box({ -0.4 - s, -0.6, z0 }, { -0.4, 0.6, z0 + t }),
        b.Box({ -0.8, -0.5 * s, z0 }, { -0.4, 0.5 * s, z0 + t }), b.Box({ 0.3, -0.6, z0 }, { 0.3 + s, 0.3, z0 + t }),
        b.Box({ 0.3, 0.3 + 1.5 * s, z0 }, { 0.3 + s, 0.3 + 2.5 * s, z0 + t }) }));
      ExpectEmbeddedWithExactTopology(tpctest::Contour(b.Scene, Unit, tolerance), 3, 0,
        "H and i at tolerance " + std::to_string(tolerance));
    }
  }
}

TEST(Embedding, ThinMeshSlab)
{
  for (const double tolerance : Tolerances)
  {
    const ToleranceCells cells = CellsOf(Unit, tolerance);
    const double z0 = cells.PlaneNear(0.0, 2) + 0.35 * cells.Width;
    SceneBuilder b;
    b.Finish(b.Mesh(tpctest::CubeMesh({ -0.7, -0.6, z0 }, { 0.7, 0.6, z0 + 0.3 * cells.Width })));
    ExpectEmbeddedWithExactTopology(tpctest::Contour(b.Scene, Unit, tolerance), 1, 0,
      "mesh slab at tolerance " + std::to_string(tolerance));
  }
}

namespace
{
/// A sphere drilled along the three axes (OpenSCAD's example001): genus 5,
/// sharp edges where the sphere meets the cylinders.
tpc::CsgTerm DrilledSphere(SceneBuilder& b)
{
  return SceneBuilder::Difference({ b.Sphere({ 0, 0, 0 }, 1.0), b.Cylinder({ 0, 0, 0 }, { 1, 0, 0 }, 0.5),
    b.Cylinder({ 0, 0, 0 }, { 0, 1, 0 }, 0.5), b.Cylinder({ 0, 0, 0 }, { 0, 0, 1 }, 0.5) });
}
} // namespace

namespace
{
// Off-centre bounds: a lattice plane through the centre would pass through
// the points where two cylinders touch, where face refinement spends its
// whole budget (tens of seconds) before the cell is split.
const Box3 DrilledSphereBounds{ { -1.02, -1.01, -1.03 }, { 1.01, 1.03, 1.02 } };
} // namespace

TEST(Embedding, SphereMinusThreeCylinders)
{
  const Box3& bounds = DrilledSphereBounds;
  for (const double tolerance : Tolerances)
  {
    SceneBuilder b;
    b.Finish(DrilledSphere(b));
    ExpectEmbeddedWithExactTopology(tpctest::Contour(b.Scene, bounds, tolerance), 1, 5,
      "implicit at tolerance " + std::to_string(tolerance));
  }
}

TEST(Embedding, SphereMinusThreeCylindersAsAMesh)
{
  // The mesh: the implicit solid's own guaranteed surface at a fine
  // tolerance (closed, manifold, embedded, genus 5), remeshed coarser.
  const Box3& bounds = DrilledSphereBounds;
  SceneBuilder source;
  source.Finish(DrilledSphere(source));
  const tpctest::ContourRun fine = tpctest::Contour(source.Scene, bounds, 1.0 / 100);
  ASSERT_TRUE(tpctest::Guaranteed(fine));
  ASSERT_EQ(fine.Report.Genus, 5);
  std::vector<Vec3> points = fine.Extraction.Mesh.Points.ToVector();
  std::vector<std::array<std::uint32_t, 3>> triangles = fine.Extraction.Mesh.Triangles.ToVector();
  ASSERT_TRUE(tpc::RepairMesh(points, triangles).MeetsAssumptions());
  for (const double tolerance : Tolerances)
  {
    SceneBuilder b;
    b.Finish(b.Mesh(tpc::MeshSolid(points, triangles)));
    ExpectEmbeddedWithExactTopology(tpctest::Contour(b.Scene, bounds, tolerance), 1, 5,
      "mesh at tolerance " + std::to_string(tolerance));
  }
}

namespace
{
/// The boundary of a Menger sponge of `level` as one mesh: the faces between
/// filled and empty voxels of a 3^level grid over the unit cube, two
/// triangles each, outward.
void MengerSponge(int level, std::vector<Vec3>& points, std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  int n = 1;
  for (int l = 0; l < level; ++l)
  {
    n *= 3;
  }
  auto filled = [&](int i, int j, int k) {
    if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n)
    {
      return false;
    }
    for (; i > 0 || j > 0 || k > 0; i /= 3, j /= 3, k /= 3)
    {
      if ((i % 3 == 1) + (j % 3 == 1) + (k % 3 == 1) >= 2)
      {
        return false;
      }
    }
    return true;
  };
  std::map<std::array<int, 3>, std::uint32_t> ids;
  auto id = [&](int i, int j, int k) {
    const auto it = ids.emplace(std::array<int, 3>{ i, j, k }, static_cast<std::uint32_t>(points.size())).first;
    if (it->second == points.size())
    {
      points.push_back({ static_cast<double>(i) / n, static_cast<double>(j) / n, static_cast<double>(k) / n });
    }
    return it->second;
  };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int k = 0; k < n; ++k)
      {
        if (!filled(i, j, k))
        {
          continue;
        }
        for (int a = 0; a < 3; ++a)
        {
          for (const int side : { 0, 1 })
          {
            int q[3] = { i, j, k };
            q[a] += side ? 1 : -1;
            if (filled(q[0], q[1], q[2]))
            {
              continue;
            }
            // The face's corners in counter-clockwise order seen from outside.
            const int u = (a + 1) % 3, v = (a + 2) % 3;
            std::array<std::uint32_t, 4> c;
            for (int m = 0; m < 4; ++m)
            {
              int p[3] = { i, j, k };
              p[a] += side;
              const int du = (m == 1 || m == 2) ? 1 : 0, dv = m >= 2 ? 1 : 0;
              p[u] += side ? du : dv;
              p[v] += side ? dv : du;
              c[static_cast<std::size_t>(m)] = id(p[0], p[1], p[2]);
            }
            triangles.push_back({ c[0], c[1], c[2] });
            triangles.push_back({ c[0], c[2], c[3] });
          }
        }
      }
    }
  }
}
} // namespace

namespace
{
/// A Menger sponge of `level` (its genus checked on the input first) at each
/// tolerance.
void ExpectMengerSpongeEmbedded(int level, long long genus)
{
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  MengerSponge(level, points, triangles);
  const tpc::MeshRepairReport input = tpc::RepairMesh(points, triangles);
  ASSERT_TRUE(input.MeetsAssumptions()) << input.Describe();
  EXPECT_EQ(input.FlippedComponents, 0u);
  ASSERT_EQ(input.Genus, genus);
  const tpc::MeshSolid sponge(points, triangles);
  const Box3 bounds{ { 0, 0, 0 }, { 1, 1, 1 } };
  for (const double tolerance : Tolerances)
  {
    SceneBuilder b;
    b.Finish(b.Mesh(sponge));
    ExpectEmbeddedWithExactTopology(
      tpctest::Contour(b.Scene, bounds, tolerance), 1, genus, "tolerance " + std::to_string(tolerance));
  }
}
} // namespace

TEST(Embedding, MengerSpongeOfLevelTwo)
{
  ExpectMengerSpongeEmbedded(2, 81);
}

TEST(Embedding, MengerSpongeOfLevelThree)
{
  ExpectMengerSpongeEmbedded(3, 1409);
}

namespace
{
/// The tetrahedron of OpenSCAD's testdata/scad/3D/issues/issue1089.scad as
/// OpenSCAD exports it to STL (six significant digits): 20 long, its four
/// vertices within 1.5e-6 of one plane - thinner than any lattice cell, two
/// dihedral angles of about 1e-7 radians.
tpc::MeshSolid Tetrahedron(std::vector<Vec3> points)
{
  std::vector<std::array<std::uint32_t, 3>> triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 1 }, { 1, 3, 2 } };
  const tpc::MeshRepairReport input = tpc::RepairMesh(points, triangles);
  EXPECT_TRUE(input.MeetsAssumptions()) << input.Describe();
  return tpc::MeshSolid(points, triangles);
}
} // namespace

TEST(Embedding, SliverTetrahedron)
{
  // Sampled cells never resolve it (566 000 cells and 30 s, falling apart
  // into pieces); exact cells keep the tetrahedron itself (ExactCell.h).
  const tpc::MeshSolid sliver = Tetrahedron({ { -0.249434, -9.94681, 7.66848 }, { -0.503165, 8.89648, 0.896037 },
    { -0.503165, -0.666568, 3.81975 }, { -0.503165, -10.2296, 6.74347 } });
  for (const double tolerance : Tolerances)
  {
    SceneBuilder b;
    b.Finish(b.Mesh(sliver));
    const tpctest::ContourRun r = tpctest::Contour(b.Scene, sliver.Bounds(), tolerance);
    ExpectEmbeddedWithExactTopology(r, 1, 0, "tolerance " + std::to_string(tolerance));
    EXPECT_GT(r.Subdivision.ExactCells, 0u);
    EXPECT_LT(r.Subdivision.Octree.Nodes.size(), 100000u) << "resolved without deep refinement";
    EXPECT_LE(r.Subdivision.HausdorffBound, r.Tolerance);
  }
}

TEST(Embedding, TetrahedronFlatterThanRoundingIsNotGuaranteed)
{
  // The same .scad's own coordinates: its volume is 2e-16 - the two sheets
  // of its surface are closer than the spacing of doubles, so its clipped
  // triangles share coordinates. The exact check sees it: closed and
  // manifold, but neither embedded nor guaranteed.
  const tpc::MeshSolid flat = Tetrahedron({ { -0.249434174697078959, -9.946811825017595865, 7.668480694904857842 },
    { -0.503165223042536525, 8.8964795095546467252, 0.896037100784631946 },
    { -0.503165223042536525, -0.66656805007570774091, 3.819754148011998751 },
    { -0.503165223042536525, -10.229615609706060653, 6.743471195239365557 } });
  SceneBuilder b;
  b.Finish(b.Mesh(flat));
  const tpctest::ContourRun r = tpctest::Contour(b.Scene, flat.Bounds(), 1.0 / 32);
  EXPECT_TRUE(r.Report.Closed && r.Report.Manifold);
  EXPECT_FALSE(r.Embedding.Embedded());
  EXPECT_FALSE(tpctest::Guaranteed(r));
  EXPECT_FALSE(r.Embedding.Cells.empty());
}
