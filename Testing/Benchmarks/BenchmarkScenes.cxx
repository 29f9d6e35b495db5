#include "BenchmarkScenes.h"

#include "vtkBox.h"
#include "vtkCylinder.h"
#include "vtkImplicitBoolean.h"
#include "vtkImplicitPolyDataDistance.h"
#include "vtkNew.h"
#include "vtkOFFReader.h"
#include "vtkPoints.h"
#include "vtkSelectEnclosedPoints.h"
#include "vtkSphere.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tpcbench
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

vtkSmartPointer<vtkPolyData> ReadOff(const std::string& path)
{
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput();
  if (mesh->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("cannot read " + path);
  }
  return mesh;
}

std::array<double, 6> Padded(const double b[6], double fraction)
{
  const double d = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  std::array<double, 6> p;
  for (int a = 0; a < 3; ++a)
  {
    p[2 * a] = b[2 * a] - fraction * d;
    p[2 * a + 1] = b[2 * a + 1] + fraction * d;
  }
  return p;
}

vtkSmartPointer<vtkImplicitFunction> EllipsoidFunction(const Ellipsoid& e)
{
  // vtkSphere of radius 1 seen through the world -> unit-sphere transform.
  vtkNew<vtkTransform> toUnit;
  toUnit->Scale(1.0 / e.SemiAxes[0], 1.0 / e.SemiAxes[1], 1.0 / e.SemiAxes[2]);
  toUnit->RotateX(-e.TiltAboutX);
  toUnit->Translate(-e.Center[0], -e.Center[1], -e.Center[2]);
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(1.0);
  sphere->SetTransform(toUnit);
  return sphere;
}

/// The demo's solid: (cube ∩ sphere) − (x, y and z cylinders).
vtkSmartPointer<vtkImplicitFunction> DemoSolid()
{
  vtkNew<vtkBox> cube;
  cube->SetBounds(-0.5, 0.5, -0.5, 0.5, -0.5, 0.5);
  vtkNew<vtkSphere> ball;
  ball->SetRadius(0.68);
  vtkNew<vtkImplicitBoolean> body;
  body->SetOperationTypeToIntersection();
  body->AddFunction(cube);
  body->AddFunction(ball);
  vtkNew<vtkImplicitBoolean> solid;
  solid->SetOperationTypeToDifference();
  solid->AddFunction(body);
  for (int axis = 0; axis < 3; ++axis)
  {
    vtkNew<vtkCylinder> hole;
    hole->SetAxis(axis == 0, axis == 1, axis == 2);
    hole->SetRadius(0.25);
    solid->AddFunction(hole);
  }
  return solid;
}

vtkSmartPointer<vtkPolyData> Translated(vtkPolyData* mesh, double x, double y, double z)
{
  vtkNew<vtkTransform> move;
  move->Translate(x, y, z);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetTransform(move);
  moved->SetInputData(mesh);
  moved->Update();
  return moved->GetOutput();
}

/// 60 disjoint spheres inside `mesh`, each at least its radius away from the
/// surface and from the others, on a deterministic lattice.
std::vector<Ellipsoid> CavitiesInside(vtkPolyData* mesh, int count)
{
  double b[6];
  mesh->GetBounds(b);
  const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  const double radius = 0.012 * diagonal;
  vtkNew<vtkImplicitPolyDataDistance> distance;
  distance->SetInput(mesh);
  vtkNew<vtkSelectEnclosedPoints> enclosed;
  enclosed->Initialize(mesh);
  std::vector<Ellipsoid> spheres;
  const int n = 40;
  for (int k = 0; k < n && static_cast<int>(spheres.size()) < count; ++k)
  {
    for (int j = 0; j < n && static_cast<int>(spheres.size()) < count; ++j)
    {
      for (int i = 0; i < n && static_cast<int>(spheres.size()) < count; ++i)
      {
        // Visit the lattice in a scrambled order so the spheres spread out.
        const int ii = (i * 17) % n, jj = (j * 23) % n, kk = (k * 29) % n;
        double c[3] = { b[0] + (ii + 0.5) * (b[1] - b[0]) / n, b[2] + (jj + 0.5) * (b[3] - b[2]) / n,
          b[4] + (kk + 0.5) * (b[5] - b[4]) / n };
        // Inside by ray parity and by the signed distance (both must agree).
        if (!enclosed->IsInsideSurface(c) || distance->EvaluateFunction(c) > -2.0 * radius)
        {
          continue;
        }
        const bool apart = std::all_of(spheres.begin(), spheres.end(), [&](const Ellipsoid& s) {
          const double dx = s.Center[0] - c[0], dy = s.Center[1] - c[1], dz = s.Center[2] - c[2];
          return std::sqrt(dx * dx + dy * dy + dz * dz) > 3.0 * radius;
        });
        if (apart)
        {
          spheres.push_back({ { c[0], c[1], c[2] }, { radius, radius, radius }, 0.0 });
        }
      }
    }
  }
  enclosed->Complete();
  if (static_cast<int>(spheres.size()) < count)
  {
    throw std::runtime_error("could not place the cavities");
  }
  return spheres;
}
} // namespace

vtkSmartPointer<vtkImplicitFunction> Scene::HolesFunction() const
{
  vtkNew<vtkImplicitBoolean> holes;
  holes->SetOperationTypeToUnion();
  for (const Ellipsoid& e : this->Holes)
  {
    holes->AddFunction(EllipsoidFunction(e));
  }
  return holes;
}

vtkSmartPointer<vtkImplicitFunction> Scene::SolidFunction() const
{
  if (this->Implicit)
  {
    return this->Implicit;
  }
  vtkNew<vtkImplicitBoolean> solid;
  solid->SetOperationTypeToDifference();
  if (this->HasPlate)
  {
    vtkNew<vtkBox> plate;
    plate->SetBounds(this->PlateBounds.data());
    solid->AddFunction(plate);
  }
  for (const auto& mesh : this->Meshes)
  {
    vtkNew<vtkImplicitPolyDataDistance> distance;
    distance->SetInput(mesh);
    solid->AddFunction(distance);
  }
  for (const Ellipsoid& e : this->Holes)
  {
    solid->AddFunction(EllipsoidFunction(e));
  }
  return solid;
}

std::vector<std::string> SceneNames()
{
  return { "armadillo", "turbine", "armadillo-cavities", "plate-ellipsoids" };
}

Scene MakeScene(const std::string& name, const std::string& meshDirectory)
{
  Scene s;
  s.Name = name;
  if (name == "armadillo" || name == "armadillo-cavities" || name == "turbine")
  {
    const std::string file = name == "turbine" ? "turbine.off" : "armadillo.off";
    s.Meshes.push_back(ReadOff(meshDirectory + "/" + file));
    s.Components = 1;
    s.Genus = name == "turbine" ? 11 : 0;
    if (name == "armadillo-cavities")
    {
      s.Holes = CavitiesInside(s.Meshes[0], 60);
      s.Components = 61;
    }
    double b[6];
    s.Meshes[0]->GetBounds(b);
    s.Bounds = Padded(b, 0.01);
    return s;
  }
  if (name == "plate-ellipsoids")
  {
    s.HasPlate = true;
    s.PlateBounds = { -1.0, 1.0, -1.0, 1.0, -0.04, 0.04 };
    for (int j = 0; j < 10; ++j)
    {
      for (int i = 0; i < 10; ++i)
      {
        s.Holes.push_back({ { -0.9 + 0.2 * i, -0.9 + 0.2 * j, 0.0 }, { 0.05, 0.03, 0.25 }, 20.0 });
      }
    }
    s.Bounds = { -1.05, 1.05, -1.05, 1.05, -0.1, 0.1 };
    s.Components = 1;
    s.Genus = 100;
    return s;
  }
  if (name == "sphere")
  {
    // The sphere of Core.QuadricCellError (certified cells, issue 17).
    vtkNew<vtkSphere> sphere;
    sphere->SetCenter(0.03, -0.05, 0.02);
    sphere->SetRadius(0.8);
    s.Implicit = sphere;
    s.IsBall = true;
    s.Ball = { 0.03, -0.05, 0.02, 0.8 };
    // (Its bounding box: the domain the filter derives, so that the
    // baselines' cells are the size the tolerance gives.)
    s.Bounds = { 0.03 - 0.8, 0.03 + 0.8, -0.05 - 0.8, -0.05 + 0.8, 0.02 - 0.8, 0.02 + 0.8 };
    s.HasBounds = false;
    s.Components = 1;
    s.Genus = 0;
    return s;
  }
  if (name == "demo-csg")
  {
    s.Implicit = DemoSolid();
    s.Bounds = { -0.6, 0.6, -0.6, 0.6, -0.6, 0.6 };
    s.HasBounds = false;
    s.Components = 1;
    s.Genus = 5;
    return s;
  }
  if (name == "couplingdown" || name == "joint-minus-knot" || name == "fandisk")
  {
    const bool boolean = name == "joint-minus-knot";
    s.Meshes.push_back(ReadOff(meshDirectory + "/" + (boolean ? "joint" : name) + ".off"));
    if (boolean)
    {
      s.Meshes.push_back(Translated(ReadOff(meshDirectory + "/knot1.off"), 0.0158, 0.0442, 0.0271));
    }
    s.Components = 1;
    s.Genus = name == "fandisk" ? 0 : 9;
    double b[6];
    s.Meshes[0]->GetBounds(b);
    s.Bounds = Padded(b, 0.01);
    s.HasBounds = false;
    return s;
  }
  throw std::runtime_error("unknown scene " + name);
}

vtkSmartPointer<vtkPolyData> TessellateEllipsoid(const Ellipsoid& e, double chordError)
{
  // A chord of angle t on radius R sags R (1 - cos(t/2)) ~ R t^2 / 8.
  const double r = std::max({ e.SemiAxes[0], e.SemiAxes[1], e.SemiAxes[2] });
  const double angle = std::sqrt(8.0 * chordError / r);
  const int resolution = std::clamp(static_cast<int>(std::ceil(2.0 * Pi / angle)), 8, 2048);
  vtkNew<vtkSphereSource> unit;
  unit->SetRadius(1.0);
  unit->SetThetaResolution(resolution);
  unit->SetPhiResolution(resolution / 2 + 1);
  vtkNew<vtkTransform> toWorld;
  toWorld->Translate(e.Center[0], e.Center[1], e.Center[2]);
  toWorld->RotateX(e.TiltAboutX);
  toWorld->Scale(e.SemiAxes[0], e.SemiAxes[1], e.SemiAxes[2]);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(unit->GetOutputPort());
  place->SetTransform(toWorld);
  place->Update();
  return place->GetOutput();
}

} // namespace tpcbench
