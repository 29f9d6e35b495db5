// Creases as polylines of the output (issue 17): of CAD meshes
// (Filters/Core/criteria/CreaseCrossing.h) - on CGAL's couplingdown and
// fandisk, every sharp crease of the input is followed by output creases
// within the tolerance, most output creases lie on input creases, and there
// are few of them - and of CSG solids (CsgCreaseCrossing.h) - a box minus a
// cylinder's creases lie on output edges, as implicit functions and as a
// Boolean of two meshes. Creases by VTK's vtkFeatureEdges (30 degrees) on the
// output; the input's creases and their angles from its triangles.
#include "CgalTestMeshes.h"
#include "FilterTestHelpers.h"

#include "vtkBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkCylinder.h"
#include "vtkCylinderSource.h"
#include "vtkImplicitBoolean.h"
#include "vtkPoints.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

namespace
{
using Point = std::array<double, 3>;
struct Segment
{
  Point A, B;
};

double Distance(const Point& p, const Segment& s)
{
  double ab[3], ap[3], ab2 = 0.0, t = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = s.B[k] - s.A[k];
    ap[k] = p[k] - s.A[k];
    ab2 += ab[k] * ab[k];
    t += ap[k] * ab[k];
  }
  t = ab2 > 0.0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    d2 += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
  }
  return std::sqrt(d2);
}

double Nearest(const Point& p, const std::vector<Segment>& segments)
{
  double d = HUGE_VAL;
  for (const Segment& s : segments)
  {
    d = std::min(d, Distance(p, s));
  }
  return d;
}

/// The edges of a triangle mesh whose two triangles' normals differ by at
/// least `degrees`.
std::vector<Segment> Creases(vtkPolyData* mesh, double degrees)
{
  std::vector<std::array<double, 3>> normals;
  std::map<std::pair<vtkIdType, vtkIdType>, std::vector<std::size_t>> edges;
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
    }
    const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    std::array<double, 3> c = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    const double length = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (double& x : c)
    {
      x /= length;
    }
    for (int k = 0; k < 3; ++k)
    {
      edges[{ std::min(ids[k], ids[(k + 1) % 3]), std::max(ids[k], ids[(k + 1) % 3]) }].push_back(normals.size());
    }
    normals.push_back(c);
  }
  std::vector<Segment> creases;
  const double cosine = std::cos(degrees * M_PI / 180.0);
  for (const auto& [e, t] : edges)
  {
    const auto& m = normals[t[0]];
    if (t.size() == 2 && m[0] * normals[t[1]][0] + m[1] * normals[t[1]][1] + m[2] * normals[t[1]][2] <= cosine)
    {
      Segment s;
      mesh->GetPoint(e.first, s.A.data());
      mesh->GetPoint(e.second, s.B.data());
      creases.push_back(s);
    }
  }
  return creases;
}

/// The largest distance from a point of `creases` (nine samples each) to
/// `output`, and how many of `creases` lie farther than `beyond` somewhere.
double WorstDistance(const std::vector<Segment>& creases, const std::vector<Segment>& output, double beyond,
  std::size_t& farther)
{
  double worst = 0.0;
  farther = 0;
  for (const Segment& s : creases)
  {
    double far = 0.0;
    for (int k = 0; k <= 8; ++k)
    {
      Point p;
      for (int a = 0; a < 3; ++a)
      {
        p[a] = s.A[a] + (s.B[a] - s.A[a]) * k / 8.0;
      }
      far = std::max(far, Nearest(p, output));
    }
    worst = std::max(worst, far);
    farther += far > beyond ? 1 : 0;
  }
  return worst;
}
} // namespace

TEST(Creases, CadMeshCreasesAreFollowedByOutputEdges)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  // Largest ratio of output to input 30-degree creases allowed (measured:
  // couplingdown 1.45, fandisk 0.53 - issue 17 asks for 1.5; 1.40 and 0.53
  // before cells had to follow their creases, CreaseFollowing.h; before cells
  // were accepted on their per-chord bound, 1.45 and 0.52; before crease
  // tiles started at 25 degrees and allowed other bends beside the crease,
  // 1.77 and 0.53; before crease cells were fanned from a crease point, 2.53
  // and 0.81; before tiles holding two creases were drawn through the
  // sharper, 3.48 and 0.82; crease tiles drawn but not predicted: 3.8 and
  // 2.6; without crease tiles, at fa5d09c, 3.5 and 3.1), and the fraction of
  // output creases lying on input creases required (measured: 0.33 and 0.42;
  // 0.34 and 0.44 before the per-chord bound - the fans' diagonals x -> x';
  // before 0.28 and 0.44, 0.14 and 0.17; drawn
  // but not predicted: 0.17 and 0.48; without: 0.014 and 0.009).
  struct Case
  {
    const char* Name;
    double MostCreases;
    double OnInputCreases;
    /// output creases' length over the input's (measured 1.54 and 1.42;
    /// 1.55 and 1.48 before cells followed their creases;
    /// 1.52 and 1.46 before the per-chord bound, 1.66 and 1.46 before
    /// crease tiles from 25 degrees, 1.97 and 1.64
    /// before crease fans, 2.41 and 1.63 before that)
    double MostLength;
  };
  for (const Case& c : { Case{ "couplingdown", 1.5, 0.3, 1.6 }, Case{ "fandisk", 0.6, 0.35, 1.55 } })
  {
    vtkSmartPointer<vtkPolyData> input = tpctest::ReadCgalMesh(c.Name);
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->SetInputData(input);
    filter->SetTolerance(1.0 / 64);
    const tpctest::FilterResult r = tpctest::Run(filter);
    EXPECT_EQ(r.Guaranteed, 1) << c.Name;
    const std::vector<Segment> input30 = Creases(input, 30.0), output30 = Creases(r.Surface, 30.0);
    // Every sharp crease (40 degrees or more: a crease barely past 30 may
    // bend the output by less at each of two edges) within the tolerance.
    std::size_t farther = 0;
    const double worst = WorstDistance(Creases(input, 40.0), output30, r.Tolerance, farther);
    EXPECT_LE(worst, r.Tolerance) << c.Name;
    // Output creases on input creases (both ends within 1 % of the tolerance
    // of one: the crease crossings lie on them, the apexes nearly).
    std::size_t on = 0;
    for (const Segment& s : output30)
    {
      on += Nearest(s.A, input30) < 0.01 * r.Tolerance && Nearest(s.B, input30) < 0.01 * r.Tolerance ? 1 : 0;
    }
    // By length too: the count rewards long output edges (fandisk's are
    // about 2.7 times as long as its input's on average), the length does not.
    auto length = [](const std::vector<Segment>& segments) {
      double sum = 0.0;
      for (const Segment& s : segments)
      {
        sum += std::hypot(s.B[0] - s.A[0], s.B[1] - s.A[1], s.B[2] - s.A[2]);
      }
      return sum;
    };
    const double lengthRatio = length(output30) / length(input30);
    EXPECT_LE(lengthRatio, c.MostLength) << c.Name;
    const double ratio = static_cast<double>(output30.size()) / static_cast<double>(input30.size());
    const double onFraction = static_cast<double>(on) / static_cast<double>(output30.size());
    EXPECT_LE(ratio, c.MostCreases) << c.Name;
    EXPECT_GE(onFraction, c.OnInputCreases) << c.Name;
    std::cout << c.Name << " at 1/64: " << r.Surface->GetNumberOfPolys() << " triangles, " << input30.size()
              << " input creases, " << output30.size() << " output creases (" << ratio << "x, " << lengthRatio
              << "x their length), " << on
              << " of them on input creases; worst distance of a sharp input crease " << worst / r.Tolerance
              << " tolerance" << std::endl;
  }
}

TEST(Creases, CadMeshCreasesAreFollowedAtFinerTolerances)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  // Every input crease of 40 degrees or more within the tolerance of an
  // output crease at finer tolerances too, where cells along chamfers and
  // grooves hold two creases (CreaseFollowing.h). Before a cell had to
  // follow its creases: couplingdown 16 creases beyond the tolerance at
  // 1/128 (at most 1.07 tolerances) and 21 at 1/256 (1.9), fandisk 5 at
  // 1/128 (1.25, by corners) and 2 at 1/256 (1.28). Cells whose apex fan
  // misses a crease take a fan around a point of a crease where that follows
  // them all (MeshCellError.h: Crease apexes) instead of splitting: the
  // most triangles allowed (measured: couplingdown 12 190 and 20 868,
  // fandisk 2 110 and 3 456; 13 974, 25 362, 2 208 and 3 644 with apex
  // fans only).
  struct Case
  {
    const char* Name;
    vtkIdType MostTriangles[2]; ///< at 1/128, 1/256
  };
  for (const Case& c : { Case{ "couplingdown", { 12800, 22000 } }, Case{ "fandisk", { 2160, 3550 } } })
  {
    const char* name = c.Name;
    vtkSmartPointer<vtkPolyData> input = tpctest::ReadCgalMesh(name);
    for (const double relative : { 1.0 / 128, 1.0 / 256 })
    {
      vtkNew<vtkTopologyPreservingContour> filter;
      filter->SetInputData(input);
      filter->SetTolerance(relative);
      const tpctest::FilterResult r = tpctest::Run(filter);
      EXPECT_EQ(r.Guaranteed, 1) << name;
      std::size_t beyond = 0;
      const double worst = WorstDistance(Creases(input, 40.0), Creases(r.Surface, 30.0), r.Tolerance, beyond);
      std::cout << name << " at 1/" << std::lround(1.0 / relative) << ": " << r.Surface->GetNumberOfPolys()
                << " triangles, worst sharp input crease " << worst / r.Tolerance << " tolerance from an output crease, "
                << beyond << " beyond it" << std::endl;
      EXPECT_EQ(beyond, 0u) << name << " at 1/" << std::lround(1.0 / relative);
      EXPECT_LE(r.Surface->GetNumberOfPolys(), c.MostTriangles[relative < 1.0 / 200 ? 1 : 0])
        << name << " at 1/" << std::lround(1.0 / relative);
    }
  }
}

TEST(Creases, DecimatedCadMeshesKeepTheirCreasesOnFewerEdges)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  // Decimate (CertifiedDecimation.h): a collapse is kept only when every
  // sharp input crease near it stays within the tolerance of an output
  // crease (SharpCreases.h), so the creases are still followed, by far fewer
  // edges - the 30-degree output creases at most 1.5 times the input's
  // (issue 17; measured: couplingdown 0.26 at 1/64 and 0.39 at 1/128 with
  // 450 and 784 triangles, fandisk 0.12 at 1/64 with 120; undecimated
  // couplingdown has 1.43 and 2.39).
  struct Case
  {
    const char* Name;
    double Relative;
  };
  for (const Case& c :
    { Case{ "couplingdown", 1.0 / 64 }, Case{ "couplingdown", 1.0 / 128 }, Case{ "fandisk", 1.0 / 64 } })
  {
    vtkSmartPointer<vtkPolyData> input = tpctest::ReadCgalMesh(c.Name);
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->SetInputData(input);
    filter->SetTolerance(c.Relative);
    filter->DecimateOn();
    const tpctest::FilterResult r = tpctest::Run(filter);
    EXPECT_EQ(r.Guaranteed, 1) << c.Name;
    std::size_t beyond = 0;
    const std::vector<Segment> output30 = Creases(r.Surface, 30.0);
    const double worst = WorstDistance(Creases(input, 40.0), output30, r.Tolerance, beyond);
    const double ratio = static_cast<double>(output30.size()) / static_cast<double>(Creases(input, 30.0).size());
    std::cout << c.Name << " decimated at 1/" << std::lround(1.0 / c.Relative) << ": "
              << r.Surface->GetNumberOfPolys() << " triangles, " << ratio
              << "x the input's 30-degree creases, worst sharp input crease " << worst / r.Tolerance
              << " tolerance from an output crease" << std::endl;
    EXPECT_EQ(beyond, 0u) << c.Name;
    EXPECT_LE(ratio, 1.5) << c.Name;
  }
}

TEST(Creases, ScanCreasesAreFollowedToo)
{
  TPC_SKIP_WITHOUT_CGAL_MESHES();
  // A scan's sharp edges (armadillo: 1 210 edges of 40 degrees or more, most
  // of them alone) are creases of the exact surface too. The prediction
  // checks the fan over a cell's own loop; the final loop's points between
  // its own changed the bends at the spokes of one cell's fan at 1/64 and
  // 1/128, and 3 edges lay up to 1.5 and 1.9 tolerances from any output
  // crease until the extraction checked the final patch and drew a fan
  // around a crease's point instead (SurfaceExtraction.cxx).
  vtkSmartPointer<vtkPolyData> input = tpctest::ReadCgalMesh("armadillo");
  for (const double relative : { 1.0 / 64, 1.0 / 128 })
  {
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->SetInputData(input);
    filter->SetTolerance(relative);
    const tpctest::FilterResult r = tpctest::Run(filter);
    EXPECT_EQ(r.Guaranteed, 1);
    std::size_t beyond = 0;
    const double worst = WorstDistance(Creases(input, 40.0), Creases(r.Surface, 30.0), r.Tolerance, beyond);
    std::cout << "armadillo at 1/" << std::lround(1.0 / relative) << ": " << r.Surface->GetNumberOfPolys()
              << " triangles, worst sharp input crease " << worst / r.Tolerance << " tolerance from an output crease, "
              << beyond << " beyond it" << std::endl;
    EXPECT_EQ(beyond, 0u) << "at 1/" << std::lround(1.0 / relative);
  }
}

namespace
{
/// Distance from a point (in the solid's own frame) to the creases of a box
/// [-1, 1]^3 minus a cylinder of radius 0.5 along y: the cube's twelve
/// edges and the two rims where the hole meets y = +-1.
double BoxMinusCylinderCreaseDistance(const Point& q)
{
  double d = HUGE_VAL;
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3; // an edge along c: |q_a| = |q_b| = 1
    if (std::fabs(q[c]) <= 1.0)
    {
      d = std::min(d, std::hypot(std::fabs(q[a]) - 1.0, std::fabs(q[b]) - 1.0));
    }
  }
  return std::min(d, std::hypot(std::hypot(q[0], q[2]) - 0.5, std::fabs(q[1]) - 1.0));
}
} // namespace

TEST(Creases, CsgCreasesAreFollowedByOutputEdges)
{
  // Issue 17's "box minus a cylinder", tilted so that no crease lies along the
  // lattice: where two primitives meet, CSG crease tiles put loop vertices on
  // the crease and the apex is moved onto it (CsgCreaseCrossing.h), so the
  // output's creases lie on the exact ones instead of zig-zagging around them.
  vtkNew<vtkTransform> tilt;
  tilt->RotateX(7.0);
  tilt->RotateZ(11.0);
  vtkNew<vtkBox> box;
  box->SetBounds(-1, 1, -1, 1, -1, 1);
  box->SetTransform(tilt);
  vtkNew<vtkCylinder> hole;
  hole->SetRadius(0.5);
  hole->SetTransform(tilt);
  vtkNew<vtkImplicitBoolean> solid;
  solid->SetOperationTypeToDifference();
  solid->AddFunction(box);
  solid->AddFunction(hole);
  vtkNew<vtkTopologyPreservingContour> filter;
  filter->SetImplicitFunction(solid);
  filter->SetBounds(-2, 2, -2, 2, -2, 2);
  filter->SetTolerance(0.01);
  const tpctest::FilterResult r = tpctest::Run(filter);
  ASSERT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Genus, 1);
  const std::vector<Segment> output30 = Creases(r.Surface, 30.0);
  ASSERT_FALSE(output30.empty());
  auto local = [&](const Point& p) {
    Point q;
    tilt->TransformPoint(p.data(), q.data()); // (an implicit function's Transform maps world to its frame)
    return q;
  };
  // Output creases on the exact creases: both ends within 10^-6 of the
  // tolerance (measured 0.90 of them; before CSG crease tiles none), and
  // their total length near the exact creases' (24 + 2 pi; measured 1.11x,
  // before 2.70x: a saw-tooth).
  std::size_t on = 0;
  double length = 0.0;
  for (const Segment& s : output30)
  {
    on += BoxMinusCylinderCreaseDistance(local(s.A)) < 1e-6 * r.Tolerance &&
        BoxMinusCylinderCreaseDistance(local(s.B)) < 1e-6 * r.Tolerance
      ? 1
      : 0;
    length += std::hypot(s.B[0] - s.A[0], s.B[1] - s.A[1], s.B[2] - s.A[2]);
  }
  const double onFraction = static_cast<double>(on) / static_cast<double>(output30.size());
  const double lengthRatio = length / (24.0 + 2.0 * M_PI);
  EXPECT_GE(onFraction, 0.8);
  EXPECT_LE(lengthRatio, 1.5);
  // Every point of the exact creases near an output crease: within the
  // tolerance everywhere (measured 0.17 at worst, by the box's corners where
  // three primitives meet), and on it for most (the median measured 10^-15
  // of the tolerance; before, 0.05).
  vtkNew<vtkTransform> untilt;
  untilt->DeepCopy(tilt);
  untilt->Inverse();
  std::vector<double> distances;
  auto sample = [&](const Point& q) {
    Point p;
    untilt->TransformPoint(q.data(), p.data());
    distances.push_back(Nearest(p, output30) / r.Tolerance);
  };
  for (int a = 0; a < 3; ++a)
  {
    for (int corner = 0; corner < 4; ++corner)
    {
      for (int k = 0; k <= 40; ++k)
      {
        Point q;
        q[a] = -1.0 + k / 20.0;
        q[(a + 1) % 3] = corner & 1 ? 1.0 : -1.0;
        q[(a + 2) % 3] = corner & 2 ? 1.0 : -1.0;
        sample(q);
      }
    }
  }
  for (const double y : { -1.0, 1.0 })
  {
    for (int k = 0; k < 80; ++k)
    {
      sample({ 0.5 * std::cos(k * M_PI / 40.0), y, 0.5 * std::sin(k * M_PI / 40.0) });
    }
  }
  std::sort(distances.begin(), distances.end());
  EXPECT_LE(distances.back(), 0.5);
  EXPECT_LE(distances[distances.size() / 2], 1e-6);
  std::cout << "box minus cylinder at 0.01: " << r.Surface->GetNumberOfPolys() << " triangles, " << output30.size()
            << " output creases, " << onFraction << " of them on the exact creases, " << lengthRatio
            << "x their length; exact creases at most " << distances.back() << " tolerance from an output crease"
            << " (median " << distances[distances.size() / 2] << ")" << std::endl;
}

namespace
{
/// `source`'s surface as a closed triangle mesh, mapped by `transform`.
vtkSmartPointer<vtkPolyData> TriangleMesh(vtkPolyDataAlgorithm* source, vtkTransform* transform)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(merged->GetOutputPort());
  moved->SetTransform(transform);
  moved->Update();
  return moved->GetOutput();
}

/// Distance from (x, z) to the boundary of the convex polygon `ring`.
double RingDistance(double x, double z, const std::vector<std::array<double, 2>>& ring)
{
  double d = HUGE_VAL;
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    const Segment edge{ { ring[k][0], 0.0, ring[k][1] },
      { ring[(k + 1) % ring.size()][0], 0.0, ring[(k + 1) % ring.size()][1] } };
    d = std::min(d, Distance({ x, 0.0, z }, edge));
  }
  return d;
}
} // namespace

TEST(Creases, MeshBooleanCreasesAreFollowedByOutputEdges)
{
  // The same box minus a cylinder as two meshes, a Boolean of meshes: where
  // the two meshes meet (the hole's rims), crease tiles put loop vertices
  // where the two meshes' traces on a tile cross and the apex between them
  // (CsgCreaseCrossing.h, LoopTriangulation.h), so the output's rims lie on
  // the exact ones; before, every tile across a rim was cut by a chord and
  // the rims were a saw-tooth (the box's own edges, creases of one mesh, were
  // already followed: CreaseCrossing.h).
  vtkNew<vtkTransform> tilt;
  tilt->RotateX(7.0);
  tilt->RotateZ(11.0);
  vtkNew<vtkTransform> untilt; // (the meshes' frame to the world)
  untilt->DeepCopy(tilt);
  untilt->Inverse();
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2.0);
  cube->SetYLength(2.0);
  cube->SetZLength(2.0);
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(0.5);
  cylinder->SetHeight(3.0);
  cylinder->SetResolution(96);
  cylinder->Update();
  // The hole's cross-section, a 96-gon: the rims are it at y = -1 and 1.
  std::vector<std::array<double, 2>> ring;
  for (vtkIdType i = 0; i < cylinder->GetOutput()->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cylinder->GetOutput()->GetPoint(i, p);
    if (p[1] > 1.0 && std::hypot(p[0], p[2]) > 0.25)
    {
      ring.push_back({ p[0], p[2] });
    }
  }
  std::sort(ring.begin(), ring.end(),
    [](const auto& a, const auto& b) { return std::atan2(a[1], a[0]) < std::atan2(b[1], b[0]); });
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  ASSERT_EQ(ring.size(), 96u);
  double rimLength = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    rimLength += 2.0 * std::hypot(ring[(k + 1) % 96][0] - ring[k][0], ring[(k + 1) % 96][1] - ring[k][1]);
  }
  // Distance from a world point to the exact rims.
  const auto rimDistance = [&](const Point& p) {
    Point q;
    tilt->TransformPoint(p.data(), q.data());
    return std::hypot(RingDistance(q[0], q[2], ring), std::fabs(q[1]) - 1.0);
  };
  for (const double relative : { 1.0 / 64, 1.0 / 128 })
  {
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->AddInputData(TriangleMesh(cube, untilt));
    filter->AddInputData(TriangleMesh(cylinder, untilt));
    filter->SetOperationToDifference();
    filter->SetTolerance(relative);
    const tpctest::FilterResult r = tpctest::Run(filter);
    ASSERT_EQ(r.Guaranteed, 1);
    EXPECT_EQ(r.Genus, 1);
    const std::vector<Segment> output30 = Creases(r.Surface, 30.0);
    // Output creases on the rims (both ends within 5 % of the tolerance: a
    // rim's apex lies on the chord between its two crease vertices, a hair
    // inside the 96-gon where they lie on two of its sides), and beside them
    // (both ends within the tolerance, not on them: the saw-tooth), by
    // length against the rims' (measured 1.02 and 0.23 at 1/64, 1.00 and
    // 0.07 at 1/128, with cells where the meshes meet larger than the
    // tolerance, their fans around points of the rim: MeshBooleanCellError.h;
    // 1.01 and 0.22, 1.01 and 0.08 with those cells at its size; before the
    // meshes' crease tiles 0.24 and 2.86, 0.25 and 2.68).
    double on = 0.0, beside = 0.0;
    for (const Segment& s : output30)
    {
      const double l = std::hypot(s.B[0] - s.A[0], s.B[1] - s.A[1], s.B[2] - s.A[2]);
      const double a = rimDistance(s.A) / r.Tolerance, b = rimDistance(s.B) / r.Tolerance;
      on += a < 0.05 && b < 0.05 ? l : 0.0;
      beside += std::max(a, b) >= 0.05 && a < 1.0 && b < 1.0 ? l : 0.0;
    }
    EXPECT_GE(on / rimLength, 0.95) << relative;
    EXPECT_LE(beside / rimLength, 0.3) << relative;
    // Every corner of the rims near an output crease (measured at most 0.094
    // and 0.092 of the tolerance, the larger cells' fans following the rim
    // within a tenth of it; 0.011 and 0.012 with those cells at the
    // tolerance's size; before crease tiles, 0.26 and 0.22: the saw-tooth's
    // teeth leave the rim between them).
    double worst = 0.0;
    for (const double y : { -1.0, 1.0 })
    {
      for (const auto& corner : ring)
      {
        Point p;
        const Point q{ corner[0], y, corner[1] };
        untilt->TransformPoint(q.data(), p.data());
        worst = std::max(worst, Nearest(p, output30) / r.Tolerance);
      }
    }
    EXPECT_LE(worst, 0.1) << relative;
    std::cout << "box minus cylinder meshes at 1/" << std::lround(1.0 / relative) << ": "
              << r.Surface->GetNumberOfPolys() << " triangles; output creases on the rims " << on / rimLength
              << "x their length, beside them " << beside / rimLength << "x; the rims' corners at most " << worst
              << " tolerance from an output crease" << std::endl;
  }
}
