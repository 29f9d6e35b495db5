#include "FacingSurfaces.h"

#include <cmath>

namespace tpc
{
namespace
{
/// l(x) = Dot(N, x) + D approximates the signed distance to a leaf's surface
/// (outward N of unit length) within Error over the cell.
struct AffineModel
{
  Vec3 N;
  double D = 0.0;
  double Error = 0.0;

  double operator()(const Vec3& p) const { return Dot(this->N, p) + this->D; }
};

/// Largest |a(x) - b(x)| over the cell's corners (the extremes of an affine
/// function over a box).
template <typename F>
double MaxOverCorners(const Box3& cell, const F& f)
{
  double m = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    const Vec3 p((c & 1) ? cell.hi[0] : cell.lo[0], (c & 2) ? cell.hi[1] : cell.lo[1],
      (c & 4) ? cell.hi[2] : cell.lo[2]);
    m = std::max(m, std::abs(f(p)));
  }
  return m;
}

bool QuadricModel(const Quadric& q, int sigma, const Box3& cell, double gap, AffineModel& model)
{
  const Vec3 c = cell.Center();
  const Vec3 g = q.Gradient(c);
  const double length = Norm(g);
  if (!(length > 0.0))
  {
    return false;
  }
  const auto& a = q.Coefficients();
  // Hessian [[2a0, a3, a5], [a3, 2a1, a4], [a5, a4, 2a2]], Frobenius norm.
  const double hessian = std::sqrt(4.0 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) +
    2.0 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]));
  const double r = 0.5 * cell.Diagonal();
  model.Error = 0.5 * hessian * r * r / length;
  if (!(model.Error <= gap))
  {
    return false; // too curved over this cell to say anything
  }
  const double s = static_cast<double>(sigma) / length;
  model.N = g * s;
  model.D = (q.Value(c) - Dot(g, c)) * s;
  return true;
}

/// Up to two planes carrying a mesh leaf's listed triangles over the cell.
int MeshModels(const MeshSolid& mesh, int sigma, const TriangleList& listed, const Box3& cell,
  double gap, AffineModel models[2])
{
  constexpr std::size_t MaximumTriangles = 256; // a flat contact lists a few
  if (listed.empty() || listed.size() > MaximumTriangles)
  {
    return 0;
  }
  int count = 0;
  for (const std::uint32_t t : listed)
  {
    AffineModel plane;
    plane.N = mesh.Normal(t) * static_cast<double>(sigma);
    plane.D = -Dot(plane.N, mesh.Vertex(t, 0));
    int k = 0;
    for (; k < count; ++k)
    {
      // How far the triangle's plane strays from model k over the cell.
      const double stray = MaxOverCorners(cell, [&](const Vec3& p) { return plane(p) - models[k](p); });
      if (stray <= 0.25 * gap)
      {
        models[k].Error = std::max(models[k].Error, stray);
        break;
      }
    }
    if (k == count)
    {
      if (count == 2)
      {
        return 0; // not (two) planes here
      }
      models[count++] = plane;
    }
  }
  return count;
}
} // namespace

bool HasFacingSurfaces(const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell,
  double gap, bool* touching)
{
  if (touching)
  {
    *touching = false;
  }
  bool facing = false;
  std::vector<AffineModel> models;
  for (const CsgLeaf& leaf : expression.Leaves())
  {
    if (leaf.Kind == PrimitiveKind::Quadric)
    {
      AffineModel m;
      if (QuadricModel(primitives.Quadrics[leaf.Primitive], leaf.Sigma, cell, gap, m))
      {
        models.push_back(m);
      }
    }
    else if (leaf.Triangles)
    {
      AffineModel m[2];
      const int n = MeshModels(primitives.Meshes[leaf.Primitive], leaf.Sigma, *leaf.Triangles, cell, gap, m);
      models.insert(models.end(), m, m + n);
    }
  }
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    for (std::size_t j = i + 1; j < models.size(); ++j)
    {
      const AffineModel &a = models[i], &b = models[j];
      const double apart = MaxOverCorners(cell, [&](const Vec3& p) { return a(p) + b(p); }) + a.Error + b.Error;
      if (Dot(a.N, b.N) < -0.5 && apart <= gap)
      {
        facing = true;
        if (!touching)
        {
          return true;
        }
        // One plane: opposite normals and no distance beyond rounding.
        *touching = *touching || apart <= 1e-12 * (cell.Diagonal() + Norm(cell.Center()));
      }
    }
  }
  return facing;
}

} // namespace tpc
