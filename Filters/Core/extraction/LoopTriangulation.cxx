#include "LoopTriangulation.h"

#include "CreasePoint.h"

#include "SymmetricEigen.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace tpc
{
namespace
{
/// Fraction of the apex region's width kept free on each side: an apex
/// recovering a feature that lies on the cell's boundary moves inward by at
/// most this much (the patch still lies in the cell, so the Hausdorff bound
/// is unchanged), and its triangles stay away from the neighbours' patches.
constexpr double ApexMargin = 1.0 / 32.0;
/// The same for an apex on a CSG crease: the crease often passes close to a
/// side of the cell, and an apex off it makes the output's crease zig-zag.
/// (Any margin keeps the fan embedded: the argument of the header needs the
/// apex strictly inside the cell only.)
constexpr double CreaseApexMargin = 1.0 / 1024.0;

Vec3 Centroid(const std::vector<LoopPoint>& loop)
{
  Vec3 m;
  for (const LoopPoint& p : loop)
  {
    m += p.Position;
  }
  return m * (1.0 / static_cast<double>(loop.size()));
}

/// Every fan triangle faces the way the surface normals at its two loop
/// points do (a fan around a badly placed apex folds over).
bool FanIsConsistent(const std::vector<LoopPoint>& loop, const Vec3& apex)
{
  const std::size_t m = loop.size();
  for (std::size_t k = 0; k < m; ++k)
  {
    const LoopPoint& a = loop[k];
    const LoopPoint& b = loop[(k + 1) % m];
    const Vec3 n = Cross(b.Position - a.Position, apex - a.Position);
    if (Dot(n, a.Normal + b.Normal) <= 0.0)
    {
      return false;
    }
  }
  return true;
}

/// The point minimizing the squared distances to the tangent planes at the
/// loop's crossings (Extended Marching Cubes' feature point), with a
/// truncated pseudo-inverse: along flat directions it stays at the centroid.
Vec3 TangentPlanesPoint(const std::vector<LoopPoint>& loop, const Vec3& centroid)
{
  double ata[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  double atb[3] = { 0, 0, 0 };
  for (const LoopPoint& p : loop)
  {
    const Vec3& n = p.Normal;
    const double d = Dot(n, p.Position - centroid);
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        ata[i][j] += n[i] * n[j];
      }
      atb[i] += n[i] * d;
    }
  }
  Vec3 delta;
  SolveTruncated(ata, atb, 0.1, delta.x);
  return centroid + delta;
}

/// The face of the cell (CubeTopology.h numbering) holding every loop point,
/// or -1.
int CommonFace(const std::vector<LoopPoint>& loop)
{
  unsigned common = 0x3F;
  for (const LoopPoint& p : loop)
  {
    common &= p.Faces;
  }
  for (int f = 0; f < 6; ++f)
  {
    if (common & (1u << f))
    {
      return f;
    }
  }
  return -1;
}

/// For a loop lying on one face of the cell the surface is a cap over that
/// face, and the tangent planes leave the apex's height free: the apex is
/// where the line from the loop's centroid along the inward normal first
/// leaves the centroid's side of the surface (16 samples across the region,
/// then bisection), or the region's middle along it.
Vec3 CapApex(const Vec3& centroid, int face, const Box3& region, const CsgExpression& expression,
  const PrimitiveSet& primitives)
{
  const int axis = face / 2;
  const double from = face % 2 ? region.hi[axis] : region.lo[axis];
  const double to = face % 2 ? region.lo[axis] : region.hi[axis];
  Vec3 p = centroid;
  auto at = [&](double t) {
    p[axis] = from + (to - from) * t;
    return p;
  };
  constexpr int Samples = 16;
  const bool start = expression.IsInside(at(0.5 / Samples), primitives);
  double lo = 0.5 / Samples, hi = -1.0;
  for (int s = 1; s < Samples && hi < 0.0; ++s)
  {
    const double t = (s + 0.5) / Samples;
    if (expression.IsInside(at(t), primitives) != start)
    {
      hi = t;
    }
    else
    {
      lo = t;
    }
  }
  if (hi < 0.0)
  {
    return at(0.5);
  }
  for (int it = 0; it < 30; ++it)
  {
    const double t = 0.5 * (lo + hi);
    (expression.IsInside(at(t), primitives) == start ? lo : hi) = t;
  }
  return at(0.5 * (lo + hi));
}

/// Newton steps from the centroid toward the surface, kept in `box`.
Vec3 ProjectedCentroid(const Vec3& centroid, const Box3& box, const CsgExpression& expression,
  const PrimitiveSet& primitives)
{
  Vec3 y = centroid;
  for (int it = 0; it < 4; ++it)
  {
    const Vec3 g = expression.Gradient(y, primitives);
    const double gg = Dot(g, g);
    if (gg <= 0.0)
    {
      break;
    }
    y = box.Clamp(y - g * (expression.Value(y, primitives) / gg));
  }
  return y;
}

/// On the surface, along the certified cell's direction n from the feature
/// point or else the centroid, where that keeps the fan consistent: the
/// certified error then has no apex term (QuadricCellError.h).
std::optional<Vec3> ApexOnSurface(const std::vector<LoopPoint>& loop, const Box3& inner,
  const QuadricCellError& surface, const Vec3& feature, const Vec3& centroid)
{
  for (const Vec3& start : { feature, inner.Clamp(centroid) })
  {
    const std::optional<Vec3> p = SurfacePointAlongDirection(surface, start, inner);
    if (p && StrictlyInside(*p, inner) && FanIsConsistent(loop, *p))
    {
      return p;
    }
  }
  return std::nullopt;
}

/// Where two quadric leaves are the surface in the cell (a CSG crease,
/// CsgCreaseCrossing.h), an apex on their crease: projected from the feature
/// point, or else from the middle of the loop's two points on the crease
/// (the crease vertices where it enters and leaves the cell); where three
/// are (a corner), at their common point. Where two leaves are and one is a
/// mesh, the middle of those two points (no projection: a mesh's crease
/// with another surface is a chain of pieces; such a surface cell is no
/// larger than the tolerance, CsgCreaseCrossing.h - a larger one where
/// meshes meet is given its apex, MeshBooleanCellError.h). Kept if it lands inside the
/// region (but for 1/1024 of its width) with the fan consistent. The output's
/// crease then runs from crease vertex to apex to crease vertex, on the
/// crease (or, with a mesh, along its chord through the cell).
std::optional<Vec3> ApexOnCrease(const std::vector<LoopPoint>& loop, const Box3& region,
  const CsgExpression& expression, const PrimitiveSet& primitives, const Vec3& feature)
{
  const Box3 inner = region.Shrunk(CreaseApexMargin);
  const std::vector<CsgLeaf> leaves = expression.Leaves();
  const bool quadrics = std::all_of(
    leaves.begin(), leaves.end(), [](const CsgLeaf& l) { return l.Kind == PrimitiveKind::Quadric; });
  const double scale = Norm(inner.hi - inner.lo);
  if (quadrics && leaves.size() == 3)
  {
    const std::optional<Vec3> corner = OntoCorner(leaves.data(), primitives, feature, scale);
    return corner && StrictlyInside(*corner, inner) && FanIsConsistent(loop, *corner) ? corner : std::nullopt;
  }
  if (leaves.size() != 2)
  {
    return std::nullopt;
  }
  std::vector<Vec3> onBoth;
  for (const LoopPoint& p : loop)
  {
    const auto distance = [&](const CsgLeaf& leaf) {
      return std::fabs(LeafValue(leaf, primitives, p.Position)) / Norm(LeafGradient(leaf, primitives, p.Position));
    };
    if (distance(leaves[0]) <= 1e-9 * scale && distance(leaves[1]) <= 1e-9 * scale)
    {
      onBoth.push_back(p.Position);
    }
  }
  if (!quadrics)
  {
    // (The middle of the two crease vertices, above.)
    if (onBoth.size() != 2)
    {
      return std::nullopt;
    }
    const Vec3 middle = (onBoth[0] + onBoth[1]) * 0.5;
    return StrictlyInside(middle, inner) && FanIsConsistent(loop, middle) ? std::optional<Vec3>(middle)
                                                                          : std::nullopt;
  }
  std::vector<Vec3> starts{ feature };
  if (onBoth.size() == 2)
  {
    starts.push_back((onBoth[0] + onBoth[1]) * 0.5);
  }
  for (const Vec3& start : starts)
  {
    const std::optional<Vec3> x = OntoCrease(leaves[0], leaves[1], primitives, start, scale);
    if (x && StrictlyInside(*x, inner) && FanIsConsistent(loop, *x))
    {
      return x;
    }
  }
  return std::nullopt;
}

Vec3 PlaceApex(const std::vector<LoopPoint>& loop, const Box3& region, bool planeSection,
  const CsgExpression& expression, const PrimitiveSet& primitives, const QuadricCellError* surface)
{
  const Vec3 centroid = Centroid(loop);
  if (planeSection)
  {
    // In the loop's plane (up to rounding): the patch is the plane section.
    return ClampStrictlyInside(centroid, region);
  }
  const Box3 inner = region.Shrunk(ApexMargin);
  const Vec3 feature = inner.Clamp(TangentPlanesPoint(loop, centroid));
  if (const std::optional<Vec3> onCrease = ApexOnCrease(loop, region, expression, primitives, feature))
  {
    return ClampStrictlyInside(*onCrease, region);
  }
  if (surface)
  {
    if (const std::optional<Vec3> onSurface = ApexOnSurface(loop, inner, *surface, feature, centroid))
    {
      return *onSurface;
    }
  }
  if (FanIsConsistent(loop, feature))
  {
    return ClampStrictlyInside(feature, region);
  }
  const int face = CommonFace(loop);
  const Vec3 fallback = face >= 0 ? inner.Clamp(CapApex(centroid, face, region, expression, primitives))
                                  : ProjectedCentroid(centroid, inner, expression, primitives);
  return ClampStrictlyInside(FanIsConsistent(loop, fallback) ? fallback : inner.Clamp(centroid), region);
}

/// The mean of the loop's normals, normalized.
Vec3 MeanNormal(const std::vector<LoopPoint>& loop)
{
  Vec3 mean;
  for (const LoopPoint& p : loop)
  {
    mean += p.Normal;
  }
  return Normalized(mean);
}

/// Among the loop points `candidate` accepts, the one whose fan satisfies
/// case 2 of the header, each triangle facing the way the normals near it
/// and `mean` do, with the shortest diagonals; -1 if none.
template <typename Candidate>
int ShortestFanPoint(const std::vector<LoopPoint>& loop, const Vec3& mean, const Candidate& candidate)
{
  const std::size_t m = loop.size();
  int best = -1;
  double bestLength = HUGE_VAL;
  for (std::size_t s = 0; s < m; ++s)
  {
    bool valid = candidate(loop[s]);
    double length = 0.0;
    for (std::size_t i = 2; i + 1 < m && valid; ++i)
    {
      valid = (loop[s].Faces & loop[(s + i) % m].Faces) == 0;
      length += Norm(loop[(s + i) % m].Position - loop[s].Position);
    }
    for (std::size_t i = 1; i + 1 < m && valid; ++i)
    {
      const LoopPoint& a = loop[(s + i) % m];
      const LoopPoint& b = loop[(s + i + 1) % m];
      const Vec3 n = Cross(a.Position - loop[s].Position, b.Position - loop[s].Position);
      valid = Dot(n, loop[s].Normal + a.Normal + b.Normal) > 0.0 && Dot(n, mean) > 0.0;
    }
    if (valid && length < bestLength)
    {
      best = static_cast<int>(s);
      bestLength = length;
    }
  }
  return best;
}
} // namespace

int LoopFanPoint(const std::vector<LoopPoint>& loop)
{
  const Vec3 mean = MeanNormal(loop);
  for (const LoopPoint& p : loop)
  {
    if (!(Dot(p.Normal, mean) >= 0.906)) // cos 25 degrees (also rejects zero normals)
    {
      return -1;
    }
  }
  return ShortestFanPoint(loop, mean, [](const LoopPoint&) { return true; });
}

int MeshEdgeFanPoint(const std::vector<LoopPoint>& loop)
{
  return ShortestFanPoint(loop, MeanNormal(loop), [](const LoopPoint& p) { return p.OnMeshEdge; });
}

unsigned FacesAsPlaced(unsigned faces, bool onMeshEdge, const Vec3& position, const Box3& cell)
{
  if (!onMeshEdge)
  {
    return faces;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const bool onFace = (faces >> (2 * axis)) & 3u;
    if (!onFace && !(position[axis] > cell.lo[axis] && position[axis] < cell.hi[axis]))
    {
      return 0x3F;
    }
  }
  return faces;
}

LoopPatch TriangulateLoop(const std::vector<LoopPoint>& loop, const ApexRoom& room, bool planeSection,
  const CsgExpression& expression, const PrimitiveSet& primitives, const QuadricCellError* surface,
  const Vec3* meshApex)
{
  LoopPatch patch;
  if (meshApex)
  {
    patch.Apex = KeptInRoom(*meshApex, Centroid(loop), room);
    return patch;
  }
  if (loop.size() == 3 && CommonFace(loop) < 0)
  {
    patch.Kind = LoopPatchKind::Triangle;
    return patch;
  }
  if (loop.size() > 3)
  {
    patch.FanPoint = LoopFanPoint(loop);
    if (patch.FanPoint >= 0)
    {
      patch.Kind = LoopPatchKind::LoopFan;
      return patch;
    }
  }
  patch.Kind = LoopPatchKind::ApexFan;
  patch.Apex = PlaceApex(loop, room.Region, planeSection, expression, primitives, surface);
  if (!room.Below.empty())
  {
    patch.Apex = KeptInRoom(patch.Apex, Centroid(loop), room);
  }
  return patch;
}

} // namespace tpc
