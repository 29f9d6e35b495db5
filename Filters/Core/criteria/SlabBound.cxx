#include "SlabBound.h"

#include "BestFitNormal.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tpc
{
namespace
{
/// The margin of the facing test, relative to |b - a| |c - a| (header:
/// Rounding).
constexpr double FacingMargin = 1e-9;

/// Whether the triangle (a, b, c) faces along `n` with room for rounding.
bool FacesAlong(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n)
{
  const Vec3 ab = b - a, ac = c - a;
  return Dot(Cross(ab, ac), n) > FacingMargin * Norm(ab) * Norm(ac);
}

/// S_C's area-weighted mean normal, unit (zero where it vanishes).
Vec3 MeanNormal(const PolygonSet& surface)
{
  Vec3 mean(0.0, 0.0, 0.0);
  for (const ConvexPolygon& q : surface)
  {
    mean = mean + q.Normal * q.TwiceArea;
  }
  const double length = Norm(mean);
  return length > 0.0 ? mean * (1.0 / length) : Vec3(0.0, 0.0, 0.0);
}

/// The unit normal of the plane fitted to S_C's corners (least squares,
/// BestFitNormal.h), turned to the side of `along`; zero where it vanishes.
Vec3 FittedNormal(const PolygonSet& surface, const Vec3& along)
{
  const Vec3 normal = BestFitNormal([&](const auto& visit) {
    for (const ConvexPolygon& q : surface)
    {
      for (const Vec3& p : q.Points)
      {
        visit(p);
      }
    }
  });
  const double length = Norm(normal);
  return length > 0.0 ? normal * ((Dot(normal, along) < 0.0 ? -1.0 : 1.0) / length) : Vec3(0.0, 0.0, 0.0);
}

/// The thickness along `n` of the slab holding S_C and the patch, or +inf
/// where a triangle of either does not face along `n`.
double SlabThickness(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, const Vec3& n)
{
  double lowest = HUGE_VAL, highest = -HUGE_VAL;
  const auto hold = [&](const Vec3& p) {
    const double h = Dot(p, n);
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
  };
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    const std::uint32_t t = surfaceTriangles[i];
    if (!FacesAlong(mesh.Vertex(t, 0), mesh.Vertex(t, 1), mesh.Vertex(t, 2), n))
    {
      return HUGE_VAL;
    }
    for (const Vec3& p : surface[i].Points)
    {
      hold(p);
    }
  }
  for (const SourceTriangle& f : patch)
  {
    if (!FacesAlong(f[0], f[1], f[2], n))
    {
      return HUGE_VAL;
    }
    for (const Vec3& p : f)
    {
      hold(p);
    }
  }
  const double thickness = highest - lowest;
  return std::isnan(thickness) ? HUGE_VAL : thickness;
}
} // namespace

double SlabPatchError(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, double chordReach, double slack, const OwnChords& chords,
  double enough, double giveUp)
{
  if (surface.empty() || patch.empty() || surfaceTriangles.size() != surface.size())
  {
    return HUGE_VAL;
  }
  const Vec3 mean = MeanNormal(surface);
  const std::array<Vec3, 2> directions = { mean, FittedNormal(surface, mean) };
  std::array<double, 2> thickness{};
  double best = HUGE_VAL;
  for (std::size_t d = 0; d < directions.size(); ++d)
  {
    thickness[d] = SlabThickness(mesh, surfaceTriangles, surface, patch, directions[d]);
    const double bound = std::sqrt(thickness[d] * thickness[d] + chordReach * chordReach) + slack;
    best = std::isnan(bound) ? best : std::min(best, bound);
  }
  // (Thinner slabs first: their local heights are likelier to settle.)
  const std::size_t first = thickness[1] < thickness[0] ? 1 : 0;
  for (std::size_t d : { first, 1 - first })
  {
    if (best <= enough || !chords.Loops)
    {
      break;
    }
    if (!(thickness[d] < HUGE_VAL))
    {
      continue;
    }
    const double local =
      LocalHeightsBound(mesh, surfaceTriangles, surface, patch, chords, directions[d], slack, std::min(giveUp, best))
      + slack;
    best = std::min(best, local);
  }
  return best;
}

} // namespace tpc
