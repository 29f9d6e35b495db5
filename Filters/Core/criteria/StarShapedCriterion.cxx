#include "StarShapedCriterion.h"

#include "ExactPredicates.h"
#include "SmallDimensionLp.h"
#include "SymmetricEigen.h"

#include <cmath>

namespace tpc
{
namespace
{
constexpr int VerificationDepth = 4;
constexpr int VerificationBudget = 200; // sub-boxes per leaf and witness

bool VerifyQuadricLeaf(
  const Quadric& q, int sigma, const StarWitness& w, const Box3& box, int depth, int& budget)
{
  if (--budget < 0)
  {
    return false;
  }
  Interval f = q.EncloseForSign(box);
  if (sigma < 0)
  {
    f = -f;
  }
  if (f.lo >= 0.0 || f.hi < 0.0)
  {
    return true; // this leaf's surface does not reach the box
  }
  if (q.EncloseStarCondition(box, w, sigma).lo > 0.0)
  {
    return true;
  }
  if (depth == 0)
  {
    return false;
  }
  Box3 pieces[8];
  const int count = SplitBox(box, pieces);
  for (int piece = 0; piece < count; ++piece)
  {
    if (!VerifyQuadricLeaf(q, sigma, w, pieces[piece], depth - 1, budget))
    {
      return false;
    }
  }
  return true;
}

/// For a mesh leaf the condition is exact and needs no refinement: on the
/// plane of triangle abc, n . (x - p) = n . (a - p), whose sign is
/// Orient3D(a, b, c, p) (a finite witness) or FacingSign(a, b, c, u) (a
/// direction u = -P). Every triangle that may meet the box is checked.
bool VerifyMeshLeaf(const MeshSolid& m, const CsgLeaf& leaf, const StarWitness& w)
{
  if (!leaf.Triangles)
  {
    return false;
  }
  const Vec3 u = w.P * -1.0;
  for (const std::uint32_t t : *leaf.Triangles)
  {
    const Vec3& a = m.Vertex(t, 0);
    const Vec3& b = m.Vertex(t, 1);
    const Vec3& c = m.Vertex(t, 2);
    const int s = w.W != 0.0 ? Orient3D(a, b, c, w.P) : FacingSign(a, b, c, u);
    if (s * leaf.Sigma <= 0)
    {
      return false;
    }
  }
  return true;
}

/// A point of a leaf's surface near the box and its unit outward normal
/// (outward of the leaf's solid, i.e. times sigma); restricted to the face
/// plane for a face.
struct SurfaceSample
{
  Vec3 Point;
  Vec3 Normal;
};

/// Samples of each leaf near the box: for a quadric, box points pulled onto
/// its surface by a few Newton steps; for a mesh, its triangles meeting the
/// box (a vertex and the exact plane's normal).
void SampleSurface(const std::vector<CsgLeaf>& leaves, const PrimitiveSet& prims,
  const Box3& box, int planeAxis, std::vector<SurfaceSample>& samples)
{
  const Vec3 c = box.Center();
  const double size = box.Diagonal();
  Box3 grown = box;
  for (int a = 0; a < 3; ++a)
  {
    grown.lo[a] -= 0.25 * size;
    grown.hi[a] += 0.25 * size;
  }
  auto add = [&](const Vec3& point, Vec3 n) {
    if (planeAxis >= 0)
    {
      n[planeAxis] = 0.0;
    }
    if (Norm(n) > 0.0)
    {
      samples.push_back({ point, Normalized(n) });
    }
  };
  for (const CsgLeaf& leaf : leaves)
  {
    if (leaf.Kind == PrimitiveKind::Mesh)
    {
      if (leaf.Triangles)
      {
        const MeshSolid& m = prims.Meshes[leaf.Primitive];
        for (const std::uint32_t t : *leaf.Triangles)
        {
          add(m.Vertex(t, 0), m.Normal(t) * static_cast<double>(leaf.Sigma));
        }
      }
      continue;
    }
    const Quadric& q = prims.Quadrics[leaf.Primitive];
    for (int s = 0; s < 9; ++s)
    {
      Vec3 x = s == 0 ? c : (box.Corner(s - 1) + c) * 0.5;
      bool ok = true;
      for (int it = 0; it < 6; ++it)
      {
        // Newton step toward the zero set, within the face plane for a face.
        Vec3 g = q.Gradient(x);
        if (planeAxis >= 0)
        {
          g[planeAxis] = 0.0;
        }
        const double gg = Dot(g, g);
        if (gg <= 0.0)
        {
          ok = false;
          break;
        }
        x = x - g * (q.Value(x) / gg);
      }
      if (ok && grown.Contains(x))
      {
        add(x, q.Gradient(x) * static_cast<double>(leaf.Sigma));
      }
    }
  }
}

/// The paper's kernel LP (5.2): the point p maximizing the margin t with
/// which it lies behind every sampled tangent plane, n . (x - p) >= t (for
/// a mesh these are the facets' exact planes, for a quadric a linearization
/// at its samples), p within a few cell sizes of the box and in the face
/// plane for a face. A positive margin gives a candidate witness point.
bool KernelPoint(const std::vector<SurfaceSample>& samples, const Box3& box, int planeAxis, Vec3& p)
{
  int axes[3], d = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (a != planeAxis)
    {
      axes[d++] = a;
    }
  }
  const double size = box.Diagonal();
  LpVector lo{}, hi{}, c{};
  for (int j = 0; j < d; ++j)
  {
    lo[j] = box.lo[axes[j]] - 4.0 * size;
    hi[j] = box.hi[axes[j]] + 4.0 * size;
  }
  lo[d] = -size;
  hi[d] = size;
  c[d] = 1.0;
  std::vector<LpHalfSpace> cons;
  cons.reserve(samples.size());
  for (const SurfaceSample& s : samples)
  {
    // n . p + t <= n . x, with the fixed coordinate of a face moved right.
    LpHalfSpace h;
    h.B = Dot(s.Normal, s.Point);
    for (int j = 0; j < d; ++j)
    {
      h.A[j] = s.Normal[axes[j]];
    }
    if (planeAxis >= 0)
    {
      h.B -= s.Normal[planeAxis] * box.lo[planeAxis];
    }
    h.A[d] = 1.0;
    cons.push_back(h);
  }
  const LpSolution sol = SolveSmallDimensionLp(d + 1, cons, c, lo, hi);
  if (!sol.Feasible || !(sol.X[d] > 1e-9 * size))
  {
    return false;
  }
  p = box.Center();
  for (int j = 0; j < d; ++j)
  {
    p[axes[j]] = sol.X[j];
  }
  return true;
}

/// The same LP for a point at infinity: the direction u (max-norm <= 1, in
/// the face plane for a face) maximizing min n . u; exact where the
/// Badoiu-Clarkson iteration only approximates.
bool KernelDirection(const std::vector<SurfaceSample>& samples, int planeAxis, Vec3& u)
{
  int axes[3], d = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (a != planeAxis)
    {
      axes[d++] = a;
    }
  }
  LpVector lo{}, hi{}, c{};
  for (int j = 0; j < d; ++j)
  {
    lo[j] = -1.0;
    hi[j] = 1.0;
  }
  lo[d] = -2.0;
  hi[d] = 2.0;
  c[d] = 1.0;
  std::vector<LpHalfSpace> cons;
  cons.reserve(samples.size());
  for (const SurfaceSample& s : samples)
  {
    LpHalfSpace h; // t - n . u <= 0
    for (int j = 0; j < d; ++j)
    {
      h.A[j] = -s.Normal[axes[j]];
    }
    h.A[d] = 1.0;
    cons.push_back(h);
  }
  const LpSolution sol = SolveSmallDimensionLp(d + 1, cons, c, lo, hi);
  if (!sol.Feasible || !(sol.X[d] > 1e-12))
  {
    return false;
  }
  u = Vec3();
  for (int j = 0; j < d; ++j)
  {
    u[axes[j]] = sol.X[j];
  }
  return true;
}

/// Direction u maximizing min_k n_k . u: the centre of the smallest cap of
/// the sphere of directions holding all normals (Badoiu-Clarkson iteration:
/// step toward the farthest normal with a shrinking step). Only a candidate;
/// it is verified afterwards.
Vec3 MaximinDirection(const std::vector<Vec3>& normals)
{
  Vec3 u;
  for (const Vec3& n : normals)
  {
    u += n;
  }
  u = Normalized(u);
  if (Norm(u) == 0.0)
  {
    u = normals.front();
  }
  for (int it = 1; it <= 100; ++it)
  {
    const Vec3* worst = &normals.front();
    double lowest = 2.0;
    for (const Vec3& n : normals)
    {
      const double d = Dot(n, u);
      if (d < lowest)
      {
        lowest = d;
        worst = &n;
      }
    }
    if (it == 1 && lowest > 0.3)
    {
      break; // the mean is comfortably inside the cone: good enough
    }
    const Vec3 next = Normalized(u + (*worst - u) * (1.0 / (it + 1.0)));
    if (Norm(next) == 0.0)
    {
      break;
    }
    u = next;
  }
  return u;
}

/// The critical point of a leaf's quadric nearest the box centre (restricted
/// to the face plane for a face): the centre of a sphere or ellipsoid, the
/// nearest axis point of a cylinder, the centre of a conic section.
bool CriticalPoint(const Quadric& q, const Box3& box, int planeAxis, Vec3& point)
{
  const auto& a = q.Coefficients();
  const double hessian[3][3] = { { 2 * a[0], a[3], a[5] }, { a[3], 2 * a[1], a[4] },
    { a[5], a[4], 2 * a[2] } };
  const Vec3 c = box.Center();
  const Vec3 g = q.Gradient(c);
  double m[3][3], rhs[3], delta[3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = (i == planeAxis || j == planeAxis) ? (i == j ? 1.0 : 0.0) : hessian[i][j];
    }
    rhs[i] = i == planeAxis ? 0.0 : -g[i];
  }
  SolveTruncated(m, rhs, 1e-9, delta);
  point = c + Vec3(delta[0], delta[1], delta[2]);
  return std::isfinite(point[0]) && std::isfinite(point[1]) && std::isfinite(point[2]) &&
    Norm(Vec3(delta[0], delta[1], delta[2])) > 0.0;
}

/// The cheap first guess, enough for most cells (small against the
/// curvature): the sum of the leaves' unit normals at the box centre (in the
/// face's plane for a face).
Vec3 MeanNormalAtCentre(const std::vector<CsgLeaf>& leaves, const PrimitiveSet& prims, const Box3& box, int planeAxis)
{
  const Vec3 c = box.Center();
  Vec3 u;
  for (const CsgLeaf& leaf : leaves)
  {
    Vec3 n;
    if (leaf.Kind == PrimitiveKind::Quadric)
    {
      n = prims.Quadrics[leaf.Primitive].Gradient(c) * static_cast<double>(leaf.Sigma);
    }
    else if (leaf.Triangles)
    {
      for (const std::uint32_t t : *leaf.Triangles)
      {
        n += prims.Meshes[leaf.Primitive].Normal(t) * static_cast<double>(leaf.Sigma);
      }
    }
    if (planeAxis >= 0)
    {
      n[planeAxis] = 0.0;
    }
    u += Normalized(n);
  }
  return u;
}

/// Witness candidates from the surface samples, cheapest first: the maximin
/// direction `u` of their normals (returned, zero without samples), the
/// centres of solids convex around a centre, and points behind the surface
/// along u.
std::vector<StarWitness> WitnessCandidates(const std::vector<CsgLeaf>& leaves, const PrimitiveSet& prims,
  const Box3& box, int planeAxis, const std::vector<SurfaceSample>& samples, Vec3& u)
{
  std::vector<StarWitness> candidates;
  std::vector<Vec3> normals;
  normals.reserve(samples.size());
  for (const SurfaceSample& sample : samples)
  {
    normals.push_back(sample.Normal);
  }
  if (!normals.empty())
  {
    u = MaximinDirection(normals);
    candidates.push_back({ u * -1.0, 0.0 });
  }
  const double planeValue = planeAxis >= 0 ? box.lo[planeAxis] : 0.0;
  for (const CsgLeaf& leaf : leaves)
  {
    // Solids convex around a centre (spheres, ellipsoids, rods) are seen
    // whole from it; holes (sigma < 0) are seen from behind their wall.
    Vec3 center;
    if (leaf.Kind == PrimitiveKind::Quadric && leaf.Sigma > 0 &&
      !prims.Quadrics[leaf.Primitive].IsLinear() &&
      CriticalPoint(prims.Quadrics[leaf.Primitive], box, planeAxis, center))
    {
      candidates.push_back({ center, 1.0 });
    }
  }
  if (Norm(u) > 0.0)
  {
    const Vec3 c = box.Center();
    for (const double k : { 0.75, 3.0 })
    {
      Vec3 p = c - u * (k * box.Diagonal());
      if (planeAxis >= 0)
      {
        p[planeAxis] = planeValue;
      }
      candidates.push_back({ p, 1.0 });
    }
  }
  return candidates;
}

bool IsStarShaped(const CsgExpressionPtr& expression, const PrimitiveSet& prims,
  const Box3& box, int planeAxis)
{
  const std::vector<CsgLeaf> leaves = expression->Leaves();
  if (leaves.empty())
  {
    return true;
  }
  const Vec3 mean = MeanNormalAtCentre(leaves, prims, box, planeAxis);
  if (Norm(mean) > 0.0 && VerifyStarWitness(*expression, prims, box, { mean * -1.0, 0.0 }, 0))
  {
    return true;
  }
  std::vector<SurfaceSample> samples;
  SampleSurface(leaves, prims, box, planeAxis, samples);
  Vec3 u;
  for (const StarWitness& w : WitnessCandidates(leaves, prims, box, planeAxis, samples, u))
  {
    if (VerifyStarWitness(*expression, prims, box, w, VerificationDepth))
    {
      return true;
    }
  }
  // Last, the kernel LPs: exact for meshes, where the heuristics above miss
  // narrow kernels (concave corners, folds).
  if (samples.empty())
  {
    return false;
  }
  Vec3 p;
  if (KernelPoint(samples, box, planeAxis, p) &&
    VerifyStarWitness(*expression, prims, box, { p, 1.0 }, VerificationDepth))
  {
    return true;
  }
  return KernelDirection(samples, planeAxis, u) &&
    VerifyStarWitness(*expression, prims, box, { u * -1.0, 0.0 }, VerificationDepth);
}
} // namespace

bool VerifyStarWitness(const CsgExpression& expression, const PrimitiveSet& primitives,
  const Box3& box, const StarWitness& witness, int refinementDepth)
{
  for (const CsgLeaf& leaf : expression.Leaves())
  {
    int budget = VerificationBudget;
    const bool ok = leaf.Kind == PrimitiveKind::Mesh
      ? VerifyMeshLeaf(primitives.Meshes[leaf.Primitive], leaf, witness)
      : VerifyQuadricLeaf(primitives.Quadrics[leaf.Primitive], leaf.Sigma, witness, box,
          refinementDepth, budget);
    if (!ok)
    {
      return false;
    }
  }
  return true;
}

bool IsStarShapedWithRespectToVoxel(
  const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& cell)
{
  return IsStarShaped(expression, primitives, cell, -1);
}

bool IsStarShapedWithRespectToFace(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& face, int axis, bool prunedToFace)
{
  if (prunedToFace)
  {
    return IsStarShaped(expression, primitives, face, axis);
  }
  const auto pruned = CsgExpression::Prune(expression, face, primitives);
  if (pruned.Sign != RegionSign::Mixed)
  {
    return true;
  }
  return IsStarShaped(pruned.Expression, primitives, face, axis);
}

} // namespace tpc
