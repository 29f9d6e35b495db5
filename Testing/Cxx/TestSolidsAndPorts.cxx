// The filter's outputs as a pipeline meets them: the surface on port 0 (the
// main result, where ParaView's simple API looks), the grid on port 1; which
// solid each triangle comes from (SolidId) and how close it is certified to
// lie (CertifiedError); the order in which the inputs are folded, and its
// reversal.
#include "FilterTestHelpers.h"

#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkImplicitPolyDataDistance.h"
#include "vtkIntArray.h"
#include "vtkMassProperties.h"
#include "vtkSphere.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>

using tpctest::FilterResult;
using tpctest::MessageRecorder;

namespace
{
vtkSmartPointer<vtkPolyData> Box(double x0, double x1, double y0, double y1, double z0, double z1)
{
  vtkNew<vtkCubeSource> box;
  box->SetBounds(x0, x1, y0, y1, z0, z1);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(box->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

double Volume(vtkPolyData* surface)
{
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(surface);
  mass->Update();
  return mass->GetVolume();
}
} // namespace

TEST(SolidsAndPorts, TheSurfaceIsPortZeroAndTheGridPortOne)
{
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(0.5);
  vtkNew<vtkTopologyPreservingContour> f;
  f->SetImplicitFunction(sphere);
  f->SetTolerance(0.05);
  f->Update();
  EXPECT_STREQ(f->GetOutputDataObject(0)->GetClassName(), "vtkPolyData");
  EXPECT_STREQ(f->GetOutputDataObject(1)->GetClassName(), "vtkHyperTreeGrid");
  EXPECT_EQ(f->GetOutputDataObject(0), f->GetSurfaceOutput());
  EXPECT_EQ(f->GetOutputDataObject(1), f->GetGridOutput());
  EXPECT_GT(f->GetSurfaceOutput()->GetNumberOfPolys(), 0);
  EXPECT_GT(f->GetGridOutput()->GetNumberOfCells(), 0);
}

TEST(SolidsAndPorts, EachTriangleNamesTheSolidItLiesOn)
{
  // A mesh sphere (input 0) united with an implicit sphere (the implicit
  // function: one past the last input), clipped by Bounds (caps: -1).
  vtkNew<vtkSphereSource> mesh;
  mesh->SetCenter(-0.3, 0, 0);
  mesh->SetRadius(0.5);
  mesh->SetThetaResolution(48);
  mesh->SetPhiResolution(32);
  vtkNew<vtkSphere> implicit;
  implicit->SetCenter(0.35, 0, 0);
  implicit->SetRadius(0.45);
  vtkNew<vtkTopologyPreservingContour> f;
  f->AddInputConnection(mesh->GetOutputPort());
  f->SetImplicitFunction(implicit);
  f->SetBounds(-1, 1, -1, 1, -1, 0.3);
  f->SetTolerance(0.02);
  const FilterResult r = tpctest::Run(f);
  ASSERT_EQ(r.Guaranteed, 1);
  vtkIntArray* solid = vtkIntArray::SafeDownCast(r.Surface->GetCellData()->GetArray("SolidId"));
  ASSERT_NE(solid, nullptr);
  ASSERT_EQ(solid->GetNumberOfTuples(), r.Surface->GetNumberOfCells());
  std::map<int, vtkIdType> count;
  vtkNew<vtkIdList> ids;
  const double h = r.HausdorffBound;
  for (vtkIdType c = 0; c < r.Surface->GetNumberOfCells(); ++c)
  {
    const int id = solid->GetValue(c);
    ++count[id];
    r.Surface->GetCellPoints(c, ids);
    double centroid[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      const double* p = r.Surface->GetPoint(ids->GetId(k));
      for (int a = 0; a < 3; ++a)
      {
        centroid[a] += p[a] / 3.0;
      }
    }
    // Each triangle is within the bound of the surface it names.
    const double toMesh = std::hypot(centroid[0] + 0.3, centroid[1], centroid[2]) - 0.5;
    const double toImplicit = std::hypot(centroid[0] - 0.35, centroid[1], centroid[2]) - 0.45;
    const double toCap = centroid[2] - 0.3;
    const double distance = id == 0 ? toMesh : id == 1 ? toImplicit : toCap;
    ASSERT_TRUE(id == 0 || id == 1 || id == -1) << id;
    ASSERT_LE(std::fabs(distance), 2 * h) << "triangle " << c << " says solid " << id;
  }
  EXPECT_GT(count[0], 100);
  EXPECT_GT(count[1], 100);
  EXPECT_GT(count[-1], 10);
}

TEST(SolidsAndPorts, ReverseInputOrderSwapsTheMinuend)
{
  // A big box and a small one overlapping it: big - small keeps most of the
  // big box; reversed, small - big is the part of the small box outside.
  vtkSmartPointer<vtkPolyData> big = Box(0, 1, 0, 1, 0, 1);
  vtkSmartPointer<vtkPolyData> small = Box(0.61, 1.37, 0.23, 0.71, 0.31, 0.83);
  double volume[2];
  for (const bool reverse : { false, true })
  {
    vtkNew<vtkTopologyPreservingContour> f;
    f->AddInputData(big);
    f->AddInputData(small);
    f->SetOperationToDifference();
    f->SetReverseInputOrder(reverse);
    f->SetTolerance(0.02);
    MessageRecorder messages(f);
    const FilterResult r = tpctest::Run(f);
    ASSERT_EQ(r.Guaranteed, 1) << messages.Warnings;
    EXPECT_EQ(r.Components, 1);
    EXPECT_EQ(r.Genus, 0);
    volume[reverse] = Volume(r.Surface);
  }
  const double overlap = 0.39 * 0.48 * 0.52;
  EXPECT_NEAR(volume[0], 1.0 - overlap, 0.01);
  EXPECT_NEAR(volume[1], 0.76 * 0.48 * 0.52 - overlap, 0.01);
}

TEST(SolidsAndPorts, EachTriangleCarriesItsCertifiedError)
{
  // CertifiedError (cell data): every point of a triangle lies within its
  // value of the exact surface, and the largest is at most HausdorffBound -
  // as extracted and decimated, for a mesh (the exact surface is the input
  // mesh, measured by vtkImplicitPolyDataDistance) and a sphere function
  // (measured as | |x - c| - r |), at each triangle's corners, edge
  // midpoints and centroid.
  vtkNew<vtkSphereSource> source;
  source->SetRadius(0.5);
  source->SetThetaResolution(48);
  source->SetPhiResolution(32);
  vtkNew<vtkTriangleFilter> mesh;
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->Update();
  vtkNew<vtkImplicitPolyDataDistance> toMesh;
  toMesh->SetInput(mesh->GetOutput());
  const double center[3] = { 0.01, -0.02, 0.03 };
  vtkNew<vtkSphere> sphere;
  sphere->SetCenter(center[0], center[1], center[2]);
  sphere->SetRadius(0.5);
  for (const bool decimate : { false, true })
  {
    for (const bool implicit : { false, true })
    {
      vtkNew<vtkTopologyPreservingContour> filter;
      if (implicit)
      {
        filter->SetImplicitFunction(sphere);
        filter->SetBounds(-1, 1, -1, 1, -1, 1);
        filter->SetTolerance(0.02);
      }
      else
      {
        filter->SetInputData(mesh->GetOutput());
        filter->SetTolerance(1.0 / 32);
      }
      filter->SetDecimate(decimate);
      const FilterResult r = tpctest::Run(filter);
      const std::string name = std::string(implicit ? "sphere" : "mesh") + (decimate ? ", decimated" : "");
      ASSERT_EQ(r.Guaranteed, 1) << name;
      auto* certified = vtkDoubleArray::SafeDownCast(r.Surface->GetCellData()->GetArray("CertifiedError"));
      ASSERT_TRUE(certified) << name;
      ASSERT_EQ(certified->GetNumberOfValues(), r.Surface->GetNumberOfPolys()) << name;
      const std::function<double(const double*)> distance = [&](const double* p) {
        return implicit ? std::fabs(std::hypot(p[0] - center[0], p[1] - center[1], p[2] - center[2]) - 0.5)
                        : std::fabs(toMesh->EvaluateFunction(const_cast<double*>(p)));
      };
      double largest = 0.0, smallest = HUGE_VAL, worst = 0.0;
      vtkNew<vtkIdList> ids;
      for (vtkIdType t = 0; t < r.Surface->GetNumberOfCells(); ++t)
      {
        const double e = certified->GetValue(t);
        largest = std::max(largest, e);
        smallest = std::min(smallest, e);
        r.Surface->GetCellPoints(t, ids);
        double corners[3][3];
        for (int k = 0; k < 3; ++k)
        {
          r.Surface->GetPoint(ids->GetId(k), corners[k]);
        }
        // Corners, edge midpoints, centroid (barycentric weights).
        const double weights[7][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.5, 0.5, 0 }, { 0, 0.5, 0.5 },
          { 0.5, 0, 0.5 }, { 1.0 / 3, 1.0 / 3, 1.0 / 3 } };
        for (const auto& w : weights)
        {
          double p[3];
          for (int a = 0; a < 3; ++a)
          {
            p[a] = w[0] * corners[0][a] + w[1] * corners[1][a] + w[2] * corners[2][a];
          }
          const double d = distance(p);
          worst = std::max(worst, d / e);
          EXPECT_LE(d, e * (1 + 1e-9) + 1e-12) << name << ", triangle " << t;
        }
      }
      EXPECT_GE(smallest, 0.0) << name;
      EXPECT_LE(largest, r.HausdorffBound * (1 + 1e-12)) << name;
      std::cout << name << ": " << r.Surface->GetNumberOfPolys() << " triangles, CertifiedError from "
                << smallest / r.Tolerance << " to " << largest / r.Tolerance << " tolerance, measured at most "
                << worst << " of it" << std::endl;
    }
  }
}
