// The benchmark's scenes (issue "Speed"), each with its exact topology:
// - "armadillo": CGAL's armadillo.off, a closed scanned mesh of 52 000
//   triangles, genus 0;
// - "turbine": CGAL's turbine.off, a mechanical part of genus 11;
// - "armadillo-cavities": armadillo minus 60 disjoint spheres inside it
//   (mesh minus implicit primitives): 61 components, genus 0;
// - "plate-ellipsoids": a thin plate minus 100 thin ellipsoids piercing it at
//   20 degrees (the paper's "curved Boolean"): 1 component, genus 100.
// Not in the timed tables, for checking that a change keeps the output
// (run_benchmark.py --compare): the demo's two scenes and a mesh Boolean:
// - "demo-csg": (cube ∩ sphere) − (three cylinders), the filter's domain
//   derived from the solid (no Bounds): 1 component, genus 5;
// - "couplingdown": CGAL's couplingdown.off, a CAD part of genus 9;
// - "fandisk": CGAL's fandisk.off, a CAD part with sharp creases, genus 0;
// - "joint-minus-knot": CGAL's joint.off minus knot1.off moved by
//   (0.0158, 0.0442, 0.0271): 1 component, genus 9 (Data/CsgReference.csv).
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
  /// Closed meshes (one solid each): the first minus the others, as the
  /// filter folds its inputs by Difference.
  std::vector<vtkSmartPointer<vtkPolyData>> Meshes;
  /// A whole implicit solid (VTK functions), for scenes that are neither
  /// meshes nor the plate; OpenVDB does not run on it, except on a ball.
  vtkSmartPointer<vtkImplicitFunction> Implicit;
  /// The implicit solid is this ball (centre, radius): OpenVDB's own
  /// level-set sphere stands for it.
  bool IsBall = false;
  std::array<double, 4> Ball{};
  /// Subtracted from the meshes / from the plate (spheres are ellipsoids
  /// with equal axes).
  std::vector<Ellipsoid> Holes;
  /// The plate (implicit scenes): a box.
  bool HasPlate = false;
  std::array<double, 6> PlateBounds{};
  /// The solid's domain (xmin, xmax, ...); the filter derives its own
  /// domain from the solid when HasBounds is false.
  std::array<double, 6> Bounds{};
  bool HasBounds = true;
  long long Components = 0;
  long long Genus = 0;

  /// The whole solid as one VTK implicit function (the VTK recipe's input;
  /// meshes through vtkImplicitPolyDataDistance).
  vtkSmartPointer<vtkImplicitFunction> SolidFunction() const;
  /// The holes' union (for the filter, combined with the meshes by Difference).
  vtkSmartPointer<vtkImplicitFunction> HolesFunction() const;
};

/// The timed scenes.
std::vector<std::string> SceneNames();
/// `meshDirectory` holds CGAL's data/meshes/*.off.
Scene MakeScene(const std::string& name, const std::string& meshDirectory);

/// A triangulated ellipsoid fine enough that its chords stay within
/// `chordError` of the exact surface (OpenVDB's input for curved primitives).
vtkSmartPointer<vtkPolyData> TessellateEllipsoid(const Ellipsoid& e, double chordError);

} // namespace tpcbench
