// Polygon and strip inputs (PolyDataToMesh.cxx, PolygonTriangulation.h):
// a closed mesh with nearly planar non-convex faces stays closed - VTK's
// triangulation dropped triangles of such faces, and the mesh was refused as
// open - and a triangle strip gives the surface its triangles give, oriented
// as they are.
#include "FilterTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkMassProperties.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using tpctest::FilterResult;
using tpctest::MessageRecorder;

namespace
{
/// A comb, counter-clockwise: a base 10 x 1 with five teeth 1 x 2.
std::vector<std::array<double, 2>> Comb()
{
  std::vector<std::array<double, 2>> corners = { { 0, 0 }, { 10, 0 } };
  for (int tooth = 4; tooth >= 0; --tooth)
  {
    corners.push_back({ 2.0 * tooth + 2.0, 3.0 });
    corners.push_back({ 2.0 * tooth + 1.0, 3.0 });
    corners.push_back({ 2.0 * tooth + 1.0, 1.0 });
    corners.push_back({ 2.0 * tooth, 1.0 });
  }
  return corners;
}

/// A face of CGAL's mpi.off (its polygon 74 1 3 31 82 77, in its plane's
/// coordinates y, z; counter-clockwise), and how far each corner is off that
/// plane (x + 10): non-convex and warped by 1e-3 of its size. VTK's
/// triangulation of it gives 2 triangles instead of 4, one outside it.
const std::vector<std::array<double, 2>> MpiFace = { { -0.926781, -0.926781 }, { 0.0, -2.00802 },
  { 6.02406, 5.02005 }, { 6.02406, -10.008 }, { 10.0401, -9.99992 }, { 10.0, 10.0 } };
const std::vector<double> MpiFaceWarp = { -0.0219, -0.02, -0.008, -0.008, 0.00008, 0.0 };

/// The prism of height `height` over `base`: each cap one polygon, the top
/// one's corners lifted by `lift` (nearly planar, as in CAD files; lift[i %
/// size]), the sides quads; outward oriented.
vtkSmartPointer<vtkPolyData> Prism(
  const std::vector<std::array<double, 2>>& base, double height, const std::vector<double>& lift)
{
  const vtkIdType n = static_cast<vtkIdType>(base.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->InsertNextPoint(base[i][0], base[i][1], 0.0);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->InsertNextPoint(base[i][0], base[i][1], height + lift[static_cast<std::size_t>(i) % lift.size()]);
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> bottom, top;
  for (vtkIdType i = 0; i < n; ++i)
  {
    bottom.push_back(n - 1 - i); // (seen from below)
    top.push_back(n + i);
    const vtkIdType side[4] = { i, (i + 1) % n, n + (i + 1) % n, n + i };
    polys->InsertNextCell(4, side);
  }
  polys->InsertNextCell(n, bottom.data());
  polys->InsertNextCell(n, top.data());
  auto prism = vtkSmartPointer<vtkPolyData>::New();
  prism->SetPoints(points);
  prism->SetPolys(polys);
  return prism;
}

/// The base's area (shoelace) and perimeter.
std::array<double, 2> AreaAndPerimeter(const std::vector<std::array<double, 2>>& base)
{
  double area = 0.0, perimeter = 0.0;
  for (std::size_t i = 0; i < base.size(); ++i)
  {
    const auto& a = base[i];
    const auto& b = base[(i + 1) % base.size()];
    area += 0.5 * (a[0] * b[1] - a[1] * b[0]);
    perimeter += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  return { area, perimeter };
}

double Volume(vtkPolyData* surface)
{
  vtkNew<vtkTriangleFilter> triangles; // (the output is triangles already; the input's caps are not)
  triangles->SetInputData(surface);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  return mass->GetVolume();
}
} // namespace

TEST(PolygonInputs, NonConvexNearlyPlanarFacesKeepTheMeshClosed)
{
  struct Case
  {
    const char* Name;
    std::vector<std::array<double, 2>> Base;
    double Height;
    std::vector<double> Lift;
  };
  const Case cases[] = { { "a comb, its top face warped by 1e-9", Comb(), 2.0, { 0.0, 1e-9 } },
    { "a face of mpi.off, warped by 1e-3", MpiFace, 5.0, MpiFaceWarp } };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->SetInputData(Prism(c.Base, c.Height, c.Lift));
    filter->SetTolerance(1.0 / 32);
    MessageRecorder messages(filter);
    const FilterResult r = tpctest::Run(filter);
    EXPECT_EQ(messages.Errors, "");
    EXPECT_EQ(messages.Warnings.find("repaired"), std::string::npos) << messages.Warnings;
    EXPECT_EQ(r.Guaranteed, 1);
    EXPECT_EQ(r.Components, 1);
    EXPECT_EQ(r.Genus, 0);
    const tpctest::IndependentTopology t = tpctest::Measure(r.Surface);
    EXPECT_EQ(t.BoundaryEdges + t.NonManifoldEdges, 0);
    EXPECT_EQ(t.Genus, 0);
    // Within the tolerance of the prism, the volumes differ by at most the
    // tolerance times the surface's area (plus what the lifts add or take).
    const auto [area, perimeter] = AreaAndPerimeter(c.Base);
    ASSERT_GT(area, 0.0) << "the base turns counter-clockwise";
    double lift = 0.0;
    for (const double l : c.Lift)
    {
      lift = std::max(lift, std::abs(l));
    }
    EXPECT_NEAR(Volume(r.Surface), area * c.Height, r.Tolerance * (2 * area + perimeter * c.Height) + lift * area);
  }
}

TEST(PolygonInputs, StripsGiveTheSurfaceTheirTrianglesGive)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkStripper> strips;
  strips->SetInputConnection(triangles->GetOutputPort());
  strips->Update();
  ASSERT_GT(strips->GetOutput()->GetNumberOfStrips(), 0);
  ASSERT_EQ(strips->GetOutput()->GetNumberOfPolys(), 0);

  FilterResult results[2];
  vtkAlgorithm* sources[2] = { triangles, strips };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkTopologyPreservingContour> filter;
    filter->SetInputConnection(sources[k]->GetOutputPort());
    filter->SetTolerance(0.05);
    MessageRecorder messages(filter);
    results[k] = tpctest::Run(filter);
    // (A strip's every other triangle is turned: taken the wrong way, the
    // repair would report an inconsistent orientation.)
    EXPECT_EQ(messages.Warnings.find("repaired"), std::string::npos) << messages.Warnings;
    EXPECT_EQ(results[k].Guaranteed, 1);
  }
  EXPECT_EQ(results[1].Surface->GetNumberOfPolys(), results[0].Surface->GetNumberOfPolys());
  EXPECT_EQ(results[1].Surface->GetNumberOfPoints(), results[0].Surface->GetNumberOfPoints());
  EXPECT_EQ(results[1].Genus, 0);
}
