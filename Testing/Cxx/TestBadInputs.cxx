// The README's table of bad inputs, row by row (issue 6): each gets defined
// behaviour and a message that says what is wrong and what to do; the
// pipeline keeps running. Rows tested elsewhere: no solid, open mesh,
// self-intersecting mesh, unsupported function, unbounded solid, tolerance
// <= 0, depth limit, coincident faces (TestFilterErrors.cxx); tangential
// contact (Core: Subdivision.TangentialContact...).
#include "FilterTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkLineSource.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using tpctest::FilterResult;
using tpctest::MessageRecorder;

namespace
{
vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> s;
  s->SetThetaResolution(16);
  s->SetPhiResolution(12);
  s->Update();
  return s->GetOutput();
}

/// The sphere's triangles rebuilt from `ids` (each triangle's point ids,
/// possibly edited) over `points`.
vtkSmartPointer<vtkPolyData> Rebuilt(vtkPoints* points, const std::vector<std::array<vtkIdType, 3>>& ids)
{
  vtkNew<vtkCellArray> polys;
  for (const auto& t : ids)
  {
    polys->InsertNextCell(3, t.data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

std::vector<std::array<vtkIdType, 3>> Triangles(vtkPolyData* mesh)
{
  std::vector<std::array<vtkIdType, 3>> ids;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n;
  const vtkIdType* p;
  for (polys->InitTraversal(); polys->GetNextCell(n, p);)
  {
    ids.push_back({ p[0], p[1], p[2] });
  }
  return ids;
}

struct Outcome
{
  FilterResult Result;
  std::string Errors, Warnings;
};

Outcome Contour(vtkPolyData* mesh, double tolerance = 0.05)
{
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputData(mesh);
  f->SetTolerance(tolerance);
  MessageRecorder messages(f);
  Outcome o;
  o.Result = tpctest::Run(f);
  o.Errors = messages.Errors;
  o.Warnings = messages.Warnings;
  return o;
}

bool Empty(const Outcome& o)
{
  return o.Result.Surface->GetNumberOfPoints() == 0 && o.Result.Grid->GetNumberOfCells() == 0;
}

/// The input was a (repaired) sphere: no error, one guaranteed genus-0 surface.
void ExpectGuaranteedSphere(const Outcome& o)
{
  EXPECT_TRUE(o.Errors.empty()) << o.Errors;
  EXPECT_EQ(o.Result.Guaranteed, 1);
  EXPECT_EQ(o.Result.Components, 1);
  EXPECT_EQ(o.Result.Genus, 0);
}
} // namespace

TEST(BadInputs, EmptyMeshIsIgnoredWithAWarning)
{
  vtkNew<vtkPolyData> empty;
  const Outcome o = Contour(empty);
  EXPECT_NE(o.Warnings.find("Input 0 is empty"), std::string::npos) << o.Warnings;
  EXPECT_NE(o.Errors.find("No solid to contour"), std::string::npos) << o.Errors;
  EXPECT_TRUE(Empty(o));
}

TEST(BadInputs, NonFiniteCoordinatesAreRefused)
{
  for (const double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    vtkSmartPointer<vtkPolyData> mesh = Sphere();
    mesh->GetPoints()->SetPoint(3, bad, 0.0, 0.0);
    const Outcome o = Contour(mesh);
    EXPECT_NE(o.Errors.find("non-finite coordinate"), std::string::npos) << o.Errors;
    EXPECT_TRUE(Empty(o));
  }
}

TEST(BadInputs, LinesAndVerticesAloneAreRefused)
{
  vtkNew<vtkLineSource> line;
  line->Update();
  const Outcome o = Contour(line->GetOutput());
  EXPECT_NE(o.Errors.find("no polygons"), std::string::npos) << o.Errors;
  EXPECT_TRUE(Empty(o));
}

TEST(BadInputs, InvertedAndInconsistentOrientationIsRepaired)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  std::vector<std::array<vtkIdType, 3>> inverted = Triangles(sphere);
  for (auto& t : inverted)
  {
    std::swap(t[0], t[1]);
  }
  const Outcome a = Contour(Rebuilt(sphere->GetPoints(), inverted));
  EXPECT_NE(a.Warnings.find("turned to face outward"), std::string::npos) << a.Warnings;
  ExpectGuaranteedSphere(a);

  std::vector<std::array<vtkIdType, 3>> mixed = Triangles(sphere);
  std::swap(mixed[5][0], mixed[5][1]);
  const Outcome b = Contour(Rebuilt(sphere->GetPoints(), mixed));
  EXPECT_NE(b.Warnings.find("inconsistent orientation repaired"), std::string::npos) << b.Warnings;
  ExpectGuaranteedSphere(b);
}

TEST(BadInputs, DuplicateVerticesDegenerateAndDuplicateTrianglesAreRepaired)
{
  // Every triangle with its own three points (an STL-like soup), plus a
  // triangle repeating a vertex and a repeated triangle.
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkPoints> soup;
  std::vector<std::array<vtkIdType, 3>> ids;
  for (const auto& t : Triangles(sphere))
  {
    std::array<vtkIdType, 3> own;
    for (int k = 0; k < 3; ++k)
    {
      own[k] = soup->InsertNextPoint(sphere->GetPoint(t[k]));
    }
    ids.push_back(own);
  }
  ids.push_back({ ids[0][0], ids[0][0], ids[0][1] });
  ids.push_back(ids[7]);
  const Outcome o = Contour(Rebuilt(soup, ids));
  EXPECT_NE(o.Warnings.find("duplicate vertices merged"), std::string::npos) << o.Warnings;
  EXPECT_NE(o.Warnings.find("degenerate"), std::string::npos) << o.Warnings;
  EXPECT_NE(o.Warnings.find("duplicate triangles"), std::string::npos) << o.Warnings;
  ExpectGuaranteedSphere(o);
}

TEST(BadInputs, NonManifoldEdgesAreComputedWithoutGuarantee)
{
  // Two tetrahedra sharing one edge: four triangles on that edge.
  vtkNew<vtkPoints> p;
  for (const auto& q : { std::array<double, 3>{ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
         { 1, 1, -1 } })
  {
    p->InsertNextPoint(q.data());
  }
  const Outcome o = Contour(Rebuilt(p, { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 4 },
                                          { 1, 5, 4 }, { 0, 4, 5 }, { 0, 5, 1 } }));
  EXPECT_NE(o.Warnings.find("non-manifold edges"), std::string::npos) << o.Warnings;
  EXPECT_NE(o.Warnings.find("TopologyGuaranteed will be 0"), std::string::npos) << o.Warnings;
  EXPECT_EQ(o.Result.Guaranteed, 0);
  const tpctest::IndependentTopology t = tpctest::Measure(o.Result.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0);
  EXPECT_EQ(t.NonManifoldEdges, 0);
}

namespace
{
/// The sphere scaled by `scale` and moved by (3, -2, 1) x scale, in double
/// precision (so that only the scale, not float rounding, differs).
vtkSmartPointer<vtkPolyData> ScaledSphere(double scale)
{
  vtkNew<vtkSphereSource> s;
  s->SetThetaResolution(16);
  s->SetPhiResolution(12);
  s->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  vtkNew<vtkTransform> t;
  t->Translate(3 * scale, -2 * scale, scale);
  t->Scale(scale, scale, scale);
  vtkNew<vtkTransformPolyDataFilter> scaled;
  scaled->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  scaled->SetTransform(t);
  scaled->SetInputConnection(s->GetOutputPort());
  scaled->Update();
  return scaled->GetOutput();
}
} // namespace

TEST(BadInputs, HugeAndTinyCoordinatesGiveTheSameAnswer)
{
  const Outcome unit = Contour(ScaledSphere(1.0));
  ExpectGuaranteedSphere(unit);
  vtkPolyData* u = unit.Result.Surface;
  // Scaled by a power of two every floating-point step scales exactly: the
  // same surface, point for point, about 1e-9 and 1e9 times as large.
  for (const double scale : { std::ldexp(1.0, -30), std::ldexp(1.0, 30) })
  {
    SCOPED_TRACE(scale);
    const Outcome o = Contour(ScaledSphere(scale));
    ExpectGuaranteedSphere(o);
    vtkPolyData* s = o.Result.Surface;
    ASSERT_EQ(s->GetNumberOfPoints(), u->GetNumberOfPoints());
    ASSERT_EQ(s->GetNumberOfPolys(), u->GetNumberOfPolys());
    EXPECT_EQ(o.Result.HausdorffBound, unit.Result.HausdorffBound * scale);
    EXPECT_EQ(o.Result.Tolerance, unit.Result.Tolerance * scale);
    for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i)
    {
      const double* p = s->GetPoint(i);
      const double* q = u->GetPoint(i);
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_EQ(p[k], q[k] * scale) << "point " << i;
      }
    }
    vtkNew<vtkIdList> a, b;
    for (vtkIdType c = 0; c < s->GetNumberOfCells(); ++c)
    {
      s->GetCellPoints(c, a);
      u->GetCellPoints(c, b);
      ASSERT_EQ(a->GetId(0), b->GetId(0));
      ASSERT_EQ(a->GetId(1), b->GetId(1));
      ASSERT_EQ(a->GetId(2), b->GetId(2));
    }
  }
  // Decimal scales round every coordinate differently, so lattice lines
  // fall a hair differently past the sphere's creases, and a few cells whose
  // certified error is near the tolerance (MeshCellError.h) decide the other
  // way: the same topology and guarantee, a bound within the tolerance and
  // near the unit one, a surface of about the same size.
  for (const double scale : { 1e-9, 1e9 })
  {
    SCOPED_TRACE(scale);
    const Outcome o = Contour(ScaledSphere(scale));
    ExpectGuaranteedSphere(o);
    EXPECT_NEAR(o.Result.Tolerance / scale, unit.Result.Tolerance, 1e-12 * unit.Result.Tolerance);
    EXPECT_LE(o.Result.HausdorffBound, o.Result.Tolerance);
    EXPECT_NEAR(o.Result.HausdorffBound / scale, unit.Result.HausdorffBound, 0.25 * unit.Result.HausdorffBound);
    EXPECT_NEAR(static_cast<double>(o.Result.Surface->GetNumberOfPolys()), static_cast<double>(u->GetNumberOfPolys()),
      0.05 * static_cast<double>(u->GetNumberOfPolys()));
  }
}

TEST(BadInputs, CoordinatesBeyondTheTrustedRangeAreRefused)
{
  // Beyond the coordinates a mesh's distances and normals are trusted with
  // (MeshSolid.h: fourth powers of lengths overflow near 1e76 and become
  // subnormal below about 1e-62 across), the answer would be the input
  // itself or a broken surface: refused, with what to do. Just inside the
  // range, the sphere as at its own scale.
  for (const double scale : { 1e65, 1e-55 })
  {
    SCOPED_TRACE(scale);
    const Outcome o = Contour(ScaledSphere(scale));
    EXPECT_NE(o.Errors.find("Scale the input"), std::string::npos) << o.Errors;
    EXPECT_TRUE(Empty(o));
  }
  for (const double scale : { 1e55, 1e-45 })
  {
    SCOPED_TRACE(scale);
    const Outcome o = Contour(ScaledSphere(scale));
    ExpectGuaranteedSphere(o);
    EXPECT_LE(o.Result.HausdorffBound, o.Result.Tolerance);
  }
}

TEST(BadInputs, ToleranceLargerThanTheDomainGivesACoarseClosedSurface)
{
  // Five times the diagonal: no size test refines; the topology tests alone
  // split the root once, and the closed sphere has a few triangles per
  // octant (how many depends on where the shifted lattice's planes cut it:
  // 8 when they met at its centre, 34 since each axis's shift is ranked on
  // its own, LatticePlacement.h).
  const Outcome coarse = Contour(Sphere(), 5.0);
  ExpectGuaranteedSphere(coarse);
  EXPECT_LE(coarse.Result.Grid->GetNumberOfCells(), 9);
  EXPECT_LE(coarse.Result.Surface->GetNumberOfPolys(), 48); // (34 measured: eight cells, four or five each)
  EXPECT_GE(coarse.Result.Surface->GetNumberOfPolys(), 4);
  EXPECT_LE(coarse.Result.HausdorffBound, coarse.Result.Tolerance);
  // (The input is a coarse polyhedron, 16 x 12: at 0.05 its cells are as
  // large as their certified error allows, MeshCellError.h.)
  const Outcome fine = Contour(Sphere(), 0.05);
  // (204 triangles against 34, measured; more than 240 before chords were
  // refined, MeshCellError.h.)
  EXPECT_GT(fine.Result.Surface->GetNumberOfPolys(), 5 * coarse.Result.Surface->GetNumberOfPolys());
}

TEST(BadInputs, AbsurdMaximumDepthIsClamped)
{
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetMaximumDepth(1000);
  EXPECT_EQ(f->GetMaximumDepth(), 40); // the lattice's reach (RootGrid.h)
  f->SetMaximumDepth(-3);
  EXPECT_GE(f->GetMaximumDepth(), 0);
  f->AddInputData(Sphere());
  f->SetTolerance(0.05);
  f->SetMaximumDepth(1000);
  const FilterResult r = tpctest::Run(f);
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Genus, 0);
}
