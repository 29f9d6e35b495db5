// The topology scenes through the VTK filter, each at three
// tolerances: the output is closed and manifold (checked with vtkFeatureEdges),
// has the exact surface's components and genus (checked with
// vtkPolyDataConnectivityFilter and V - E + F from vtkExtractEdges), and the
// filter reports TopologyGuaranteed = 1.
#include "FilterTestHelpers.h"

#include "vtkBox.h"
#include "vtkContourFilter.h"
#include "vtkCylinder.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImplicitBoolean.h"
#include "vtkMath.h"
#include "vtkQuadric.h"
#include "vtkSampleFunction.h"
#include "vtkSphere.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using tpctest::Contour;
using tpctest::FilterResult;
using tpctest::Measure;

namespace
{
vtkSmartPointer<vtkSphere> MakeSphere(double x, double y, double z, double r)
{
  auto s = vtkSmartPointer<vtkSphere>::New();
  s->SetCenter(x, y, z);
  s->SetRadius(r);
  return s;
}

vtkSmartPointer<vtkImplicitBoolean> Combine(int op, std::initializer_list<vtkImplicitFunction*> fs)
{
  auto b = vtkSmartPointer<vtkImplicitBoolean>::New();
  b->SetOperationType(op);
  for (vtkImplicitFunction* f : fs)
  {
    b->AddFunction(f);
  }
  return b;
}

/// Gap between the two spheres: 0.2 % of the diagonal of their bounding box
/// (x in [-1 - g/2, 1 + g/2], y and z in [-0.5, 0.5]).
double TwoSphereGap()
{
  double g = 0.0;
  for (int i = 0; i < 50; ++i)
  {
    g = 0.002 * std::sqrt((2.0 + g) * (2.0 + g) + 2.0);
  }
  return g;
}

struct Scene
{
  const char* Name;
  std::function<vtkSmartPointer<vtkImplicitFunction>()> Make;
  int Components;
  int Genus;
  double Tolerances[3];
};

vtkSmartPointer<vtkImplicitFunction> TwoSeparateSpheres()
{
  const double g = TwoSphereGap();
  return Combine(vtkImplicitBoolean::VTK_UNION,
    { MakeSphere(-0.5 - g / 2, 0, 0, 0.5), MakeSphere(0.5 + g / 2, 0, 0, 0.5) });
}

vtkSmartPointer<vtkImplicitFunction> BoxMinusCylinder()
{
  vtkNew<vtkBox> box;
  box->SetBounds(-0.5, 0.5, -0.5, 0.5, -0.3, 0.3);
  vtkNew<vtkCylinder> cyl;
  cyl->SetCenter(0.05, 0.02, 0.0);
  cyl->SetAxis(0, 0, 1);
  cyl->SetRadius(0.2);
  return Combine(vtkImplicitBoolean::VTK_DIFFERENCE, { box, cyl });
}

/// A thin plate pierced by a 6 x 6 array of thin ellipsoids (vtkSphere with a
/// scaling vtkTransform).
vtkSmartPointer<vtkImplicitFunction> PlateWithEllipsoidHoles()
{
  vtkNew<vtkBox> plate;
  plate->SetBounds(0, 1, 0, 1, 0.45, 0.55);
  auto diff = Combine(vtkImplicitBoolean::VTK_DIFFERENCE, { plate });
  for (int i = 0; i < 6; ++i)
  {
    for (int j = 0; j < 6; ++j)
    {
      vtkNew<vtkTransform> t;
      t->Scale(1.0 / 0.02, 1.0 / 0.04, 1.0 / 0.2);
      t->Translate(-(i + 0.5) / 6.0, -(j + 0.5) / 6.0, -0.5);
      auto e = MakeSphere(0, 0, 0, 1.0);
      e->SetTransform(t);
      diff->AddFunction(e);
    }
  }
  return diff;
}

const Scene Scenes[] = {
  { "Sphere", [] { return vtkSmartPointer<vtkImplicitFunction>(MakeSphere(0.1, 0.2, 0.3, 0.5)); },
    1, 0, { 0.05, 0.02, 0.01 } },
  { "TwoSpheresWithNarrowGap", TwoSeparateSpheres, 2, 0, { 0.05, 0.02, 0.01 } },
  { "BoxMinusCylinder", BoxMinusCylinder, 1, 1, { 0.05, 0.02, 0.01 } },
  { "PlateMinus36Ellipsoids", PlateWithEllipsoidHoles, 1, 36, { 0.05, 0.02, 0.01 } },
  { "TwoOverlappingSpheres",
    [] {
      return vtkSmartPointer<vtkImplicitFunction>(Combine(vtkImplicitBoolean::VTK_UNION,
        { MakeSphere(-0.3, 0, 0, 0.5), MakeSphere(0.3, 0.05, 0, 0.45) }));
    },
    1, 0, { 0.05, 0.02, 0.01 } },
};

class TopologyScenes : public ::testing::TestWithParam<std::tuple<int, int>>
{
};
} // namespace

TEST_P(TopologyScenes, SameComponentsAndGenusClosedManifoldGuaranteed)
{
  const Scene& scene = Scenes[std::get<0>(GetParam())];
  const double tolerance = scene.Tolerances[std::get<1>(GetParam())];
  auto function = scene.Make();
  const FilterResult r = Contour(function, tolerance);
  ASSERT_GT(r.Surface->GetNumberOfPolys(), 0);
  EXPECT_EQ(r.Guaranteed, 1) << scene.Name << " at " << tolerance;
  EXPECT_EQ(r.Unresolved, 0);
  EXPECT_EQ(r.Components, scene.Components);
  EXPECT_EQ(r.Genus, scene.Genus);

  const tpctest::IndependentTopology t = Measure(r.Surface);
  EXPECT_EQ(t.BoundaryEdges, 0);
  EXPECT_EQ(t.NonManifoldEdges, 0);
  EXPECT_EQ(t.Components, scene.Components);
  EXPECT_EQ(t.Genus, scene.Genus);
  EXPECT_EQ(t.Euler, r.Euler);

  // The proven Hausdorff bound never exceeds the tolerance asked for.
  EXPECT_GT(r.HausdorffBound, 0.0);
  EXPECT_LE(r.HausdorffBound, r.Tolerance * (1.0 + 1e-9));
}

INSTANTIATE_TEST_SUITE_P(AllScenes, TopologyScenes,
  ::testing::Combine(::testing::Range(0, 5), ::testing::Range(0, 3)),
  [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
    return std::string(Scenes[std::get<0>(info.param)].Name) + "_Tolerance" +
      std::to_string(std::get<1>(info.param));
  });

TEST(TopologyScenes, SphereVerticesAreWithinTheToleranceOfTheExactSphere)
{
  const double relative = 0.02;
  const FilterResult r = Contour(MakeSphere(0.1, 0.2, 0.3, 0.5), relative);
  const double diagonal = std::sqrt(3.0);
  const double epsilon = relative * diagonal;
  EXPECT_LE(r.HausdorffBound, epsilon * (1 + 1e-9));
  double worst = 0.0;
  for (vtkIdType i = 0; i < r.Surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    r.Surface->GetPoint(i, p);
    const double d = std::sqrt(vtkMath::Distance2BetweenPoints(p, std::array<double, 3>{ 0.1, 0.2, 0.3 }.data()));
    worst = std::max(worst, std::fabs(d - 0.5));
  }
  EXPECT_LE(worst, epsilon);
  // Edge crossings are roots of the exact field, not interpolations: most
  // vertices lie on the sphere to rounding.
  EXPECT_GT(worst, 0.0);
}

TEST(TopologyScenes, UniformGridAtTheSameToleranceMergesTheTwoSpheres)
{
  // Why the adaptive criteria matter: Marching Cubes on a uniform grid whose
  // cells have the same diagonal as ours joins the two spheres.
  // Samples symmetric about the gap (an even count along x, so none sits in
  // the 0.005-wide gap): inside samples of both spheres face each other
  // across it and Marching Cubes joins them.
  const double g = TwoSphereGap();
  const double diagonal = std::sqrt((2 + g) * (2 + g) + 2.0);
  const double spacing = 0.05 * diagonal / std::sqrt(3.0);
  const int half[3] = { static_cast<int>(std::ceil((1 + g / 2) / spacing)) + 1,
    static_cast<int>(std::ceil(0.5 / spacing)) + 1, static_cast<int>(std::ceil(0.5 / spacing)) + 1 };
  vtkNew<vtkSampleFunction> sample;
  sample->SetImplicitFunction(TwoSeparateSpheres());
  sample->SetModelBounds(-(half[0] - 0.5) * spacing, (half[0] - 0.5) * spacing,
    -(half[1] - 0.5) * spacing, (half[1] - 0.5) * spacing, -(half[2] - 0.5) * spacing,
    (half[2] - 0.5) * spacing);
  sample->SetSampleDimensions(2 * half[0], 2 * half[1], 2 * half[2]);
  sample->ComputeNormalsOff();
  vtkNew<vtkFlyingEdges3D> mc;
  mc->SetInputConnection(sample->GetOutputPort());
  mc->SetValue(0, 0.0);
  mc->Update();
  EXPECT_EQ(Measure(mc->GetOutput()).Components, 1);

  const FilterResult r = Contour(TwoSeparateSpheres(), 0.05);
  EXPECT_EQ(r.Components, 2);
}

TEST(TopologyScenes, ClassicCsgTreeHasGenusFive)
{
  // (box ∩ sphere) − (three orthogonal cylinders), the textbook CSG tree.
  vtkNew<vtkBox> box;
  box->SetBounds(-0.5, 0.5, -0.5, 0.5, -0.5, 0.5);
  auto body = Combine(vtkImplicitBoolean::VTK_INTERSECTION, { box, MakeSphere(0, 0, 0, 0.68) });
  vtkNew<vtkCylinder> cx, cy, cz;
  cx->SetAxis(1, 0, 0);
  cy->SetAxis(0, 1, 0);
  cz->SetAxis(0, 0, 1);
  for (vtkCylinder* c : { cx.Get(), cy.Get(), cz.Get() })
  {
    c->SetRadius(0.25);
  }
  auto holes = Combine(vtkImplicitBoolean::VTK_UNION, { cx, cy, cz });
  const FilterResult r = Contour(Combine(vtkImplicitBoolean::VTK_DIFFERENCE, { body, holes }), 0.02);
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Components, 1);
  EXPECT_EQ(r.Genus, 5);
  EXPECT_EQ(Measure(r.Surface).Genus, 5);
}

TEST(TopologyScenes, RotatedTransformedBoxAndQuadric)
{
  // A rotated box (Transform on vtkBox) unioned with an ellipsoid given as a
  // vtkQuadric: transforms and general quadrics are honoured.
  vtkNew<vtkBox> box;
  box->SetBounds(-0.4, 0.4, -0.2, 0.2, -0.1, 0.1);
  vtkNew<vtkTransform> t;
  t->RotateZ(30);
  t->RotateX(20);
  box->SetTransform(t);
  vtkNew<vtkQuadric> ellipsoid; // x^2/0.09 + y^2/0.04 + (z-0.5)^2/0.01 - 1
  ellipsoid->SetCoefficients(1 / 0.09, 1 / 0.04, 1 / 0.01, 0, 0, 0, 0, 0, -1.0 / 0.01, 0.25 / 0.01 - 1);
  const FilterResult r = Contour(Combine(vtkImplicitBoolean::VTK_UNION, { box, ellipsoid }), 0.02);
  EXPECT_EQ(r.Guaranteed, 1);
  EXPECT_EQ(r.Components, 2);
  EXPECT_EQ(r.Genus, 0);
  // The rotated box's corners are in the output's bounds.
  double b[6];
  r.Surface->GetBounds(b);
  double corner[3] = { 0.4, 0.2, 0.1 };
  t->GetInverse()->TransformPoint(corner, corner);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_LE(b[2 * a], corner[a] + 0.05);
    EXPECT_GE(b[2 * a + 1], corner[a] - 0.05);
  }
}
