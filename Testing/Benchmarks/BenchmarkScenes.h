// The benchmark's scenes (issue "Speed"), each with its exact topology:
// - "armadillo": CGAL's armadillo.off, a closed scanned mesh of 52 000
//   triangles, genus 0;
// - "turbine": CGAL's turbine.off, a mechanical part of genus 11;
// - "armadillo-cavities": armadillo minus 60 disjoint spheres inside it
//   (mesh minus implicit primitives): 61 components, genus 0;
// - "plate-ellipsoids": a thin plate minus 100 thin ellipsoids piercing it at
//   20 degrees (the paper's "curved Boolean"): 1 component, genus 100.
#pragma once

#include "vtkImplicitFunction.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

namespace tpcbench
{

struct Ellipsoid
{
  std::array<double, 3> Center;
  std::array<double, 3> SemiAxes;
  double TiltAboutX = 0.0; ///< degrees
};

struct Scene
{
  std::string Name;
  /// Closed meshes (one solid each), unioned.
  std::vector<vtkSmartPointer<vtkPolyData>> Meshes;
  /// Subtracted from the meshes / from the plate (spheres are ellipsoids
  /// with equal axes).
  std::vector<Ellipsoid> Holes;
  /// The plate (implicit scenes): a box.
  bool HasPlate = false;
  std::array<double, 6> PlateBounds{};
  /// The solid's domain (xmin, xmax, ...).
  std::array<double, 6> Bounds{};
  long long Components = 0;
  long long Genus = 0;

  /// The whole solid as one VTK implicit function (the VTK recipe's input;
  /// meshes through vtkImplicitPolyDataDistance).
  vtkSmartPointer<vtkImplicitFunction> SolidFunction() const;
  /// The holes' union (for the filter, combined with the meshes by Difference).
  vtkSmartPointer<vtkImplicitFunction> HolesFunction() const;
};

std::vector<std::string> SceneNames();
/// `meshDirectory` holds CGAL's data/meshes/*.off.
Scene MakeScene(const std::string& name, const std::string& meshDirectory);

/// A triangulated ellipsoid fine enough that its chords stay within
/// `chordError` of the exact surface (OpenVDB's input for curved primitives).
vtkSmartPointer<vtkPolyData> TessellateEllipsoid(const Ellipsoid& e, double chordError);

} // namespace tpcbench
