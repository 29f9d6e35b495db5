// Helpers for tests: build CSG scenes of quadrics directly in the core.
#pragma once

#include "BestLatticePlacement.h"

namespace tpctest
{
using tpc::CsgTerm;

/// One cubic root cell of side `size` at `origin`, with a lattice of
/// 2^`maxDepth` spacings.
inline tpc::RootGrid SingleRoot(const tpc::Vec3& origin, double size, int maxDepth)
{
  tpc::RootGrid grid;
  grid.Origin = origin;
  grid.RootSize = size;
  grid.MaxDepth = maxDepth;
  return grid;
}

using tpc::Quadric;
using tpc::Vec3;

/// A scene for the subdivision's own tests (primitives and expression) that
/// also keeps the solid's term, for whole runs through tpc::Contour.
struct Scene : tpc::ImplicitScene
{
  CsgTerm Solid;
};

struct SceneBuilder
{
  tpctest::Scene Scene;

  CsgTerm Add(const Quadric& q)
  {
    Scene.Primitives.Quadrics.push_back(q);
    return CsgTerm::Primitive(static_cast<int>(Scene.Primitives.Quadrics.size() - 1));
  }
  CsgTerm Mesh(tpc::MeshSolid m)
  {
    Scene.Primitives.Meshes.push_back(std::move(m));
    return CsgTerm::Mesh(static_cast<int>(Scene.Primitives.Meshes.size() - 1));
  }
  CsgTerm Sphere(const Vec3& c, double r) { return Add(Quadric::Sphere(c, r)); }
  CsgTerm Ellipsoid(const Vec3& c, const Vec3& axes) { return Add(Quadric::Ellipsoid(c, axes)); }
  CsgTerm Cylinder(const Vec3& c, const Vec3& axis, double r)
  {
    return Add(Quadric::Cylinder(c, axis, r));
  }
  CsgTerm Box(const Vec3& lo, const Vec3& hi)
  {
    std::vector<CsgTerm> planes;
    for (int a = 0; a < 3; ++a)
    {
      Vec3 n, o;
      n[a] = 1.0;
      o[a] = hi[a];
      planes.push_back(Add(Quadric::Plane(o, n)));
      n[a] = -1.0;
      o[a] = lo[a];
      planes.push_back(Add(Quadric::Plane(o, n)));
    }
    return CsgTerm::Combine(CsgTerm::Op::Intersection, planes);
  }
  static CsgTerm Union(std::vector<CsgTerm> t) { return CsgTerm::Combine(CsgTerm::Op::Union, std::move(t)); }
  static CsgTerm Intersection(std::vector<CsgTerm> t)
  {
    return CsgTerm::Combine(CsgTerm::Op::Intersection, std::move(t));
  }
  static CsgTerm Difference(std::vector<CsgTerm> t)
  {
    return CsgTerm::Combine(CsgTerm::Op::Difference, std::move(t));
  }

  /// Sets the scene's expression; returns the pruned-free expression.
  tpc::CsgExpressionPtr Finish(const CsgTerm& t)
  {
    Scene.Solid = t;
    Scene.Expression = tpc::CsgExpression::FromTerm(t);
    return Scene.Expression;
  }
};
} // namespace tpctest
