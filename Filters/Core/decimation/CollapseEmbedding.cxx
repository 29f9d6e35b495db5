#include "CollapseEmbedding.h"

#include "ExactPredicates.h"
#include "SelfIntersection.h"
#include "SolidBoundary.h"

#include <array>

namespace tpc
{
namespace
{

/// p in the closed tetrahedron t of orientation `sign` (exact): no face
/// sees p on the side opposite its fourth vertex.
bool InClosedTetrahedron(const Vec3& p, const std::array<Vec3, 4>& t, int sign)
{
  for (int i = 0; i < 4; ++i)
  {
    std::array<Vec3, 4> q = t;
    q[i] = p;
    if (Orient3D(q[0], q[1], q[2], q[3]) == -sign)
    {
      return false;
    }
  }
  return true;
}

/// Whether the star's component has a vertex outside `box`: a walk over its
/// vertices inside the box, from From (most stars find one among the
/// neighbours of their link). When it has none, `inside` holds them all.
/// (`marks` stamps vertices here: the triangle marks of the examination,
/// free between its searches.)
bool LeavesTheBox(const LiveSurface& surface, const Collapse& c, const Box3& box, VisitMarks& marks,
  std::vector<std::uint32_t>& inside)
{
  marks.Start(surface.Around.size());
  inside.assign(1, c.From);
  marks.First(c.From);
  for (std::size_t next = 0; next < inside.size(); ++next)
  {
    for (const std::uint32_t t : surface.Around[inside[next]])
    {
      for (const std::uint32_t x : surface.Triangles[t])
      {
        if (!box.Contains(surface.P[x]))
        {
          return true;
        }
        if (marks.First(x))
        {
          inside.push_back(x);
        }
      }
    }
  }
  return false;
}

/// Whether the component whose vertices are `vertices` encloses a volume of
/// the same sign after the collapse as before, both decided
/// (SolidBoundary.h, EnclosedVolume).
bool KeepsItsSide(const LiveSurface& surface, const Collapse& c, const std::vector<std::uint32_t>& vertices)
{
  EnclosedVolume before, after;
  for (const std::uint32_t w : vertices)
  {
    for (const std::uint32_t t : surface.Around[w])
    {
      const Triangle& triangle = surface.Triangles[t];
      // (Each triangle once: from its first corner.)
      if (triangle[0] != w)
      {
        continue;
      }
      before.Add(surface.P, triangle);
      if (!Holds(triangle, c.From))
      {
        after.Add(surface.P, triangle);
      }
    }
  }
  for (const Triangle& made : c.Made)
  {
    after.Add(surface.P, made);
  }
  return before.Sign() != 0 && before.Sign() == after.Sign();
}

} // namespace

bool MeetsAnother(const LiveSurface& surface, const Collapse& c, VisitMarks& marks)
{
  for (std::size_t i = 0; i < c.Made.size(); ++i)
  {
    for (std::size_t j = i + 1; j < c.Made.size(); ++j)
    {
      if (TrianglesMeetImproperly(surface.P, c.Made[i], c.Made[j]))
      {
        return true;
      }
    }
  }
  bool meets = false;
  for (const Triangle& t : c.Made)
  {
    // (The star's triangles are replaced by the made ones.)
    surface.ForEachOther(c, TriangleBox(surface.P, t), marks,
      [&](std::uint32_t o) { meets = meets || TrianglesMeetImproperly(surface.P, t, surface.Triangles[o]); });
    if (meets)
    {
      return true;
    }
  }
  return false;
}

bool SweepsOverAnother(const LiveSurface& surface, const Collapse& c, VisitMarks& marks)
{
  const Vec3* P = surface.P;
  struct Swept
  {
    std::array<Vec3, 4> Corners;
    std::uint32_t A, B;
    int Sign;
  };
  std::vector<Swept> swept;
  for (const Triangle& t : c.Made)
  {
    const int k = t[0] == c.To ? 0 : (t[1] == c.To ? 1 : 2);
    const std::uint32_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
    const int sign = Orient3D(P[c.From], P[c.To], P[a], P[b]);
    if (sign != 0)
    {
      swept.push_back({ { P[c.From], P[c.To], P[a], P[b] }, a, b, sign });
    }
  }
  if (swept.empty())
  {
    return false;
  }
  const Box3 box = BoxOf(P, surface.StarOf(c)); // (N's vertices are O's)
  // (The pocket lies in the box: it may hold all the rest of a component
  // that does not leave it, unseen by the vertex test below - header.)
  std::vector<std::uint32_t> component;
  if (!LeavesTheBox(surface, c, box, marks, component) && !KeepsItsSide(surface, c, component))
  {
    return true;
  }
  bool sweeps = false;
  surface.ForEachOther(c, box, marks, [&](std::uint32_t o) {
    for (const std::uint32_t v : surface.Triangles[o])
    {
      if (sweeps || v == c.To || !box.Contains(P[v]))
      {
        continue;
      }
      for (const Swept& s : swept)
      {
        // (A link vertex is a corner of its own tetrahedra.)
        if (v != s.A && v != s.B && InClosedTetrahedron(P[v], s.Corners, s.Sign))
        {
          sweeps = true;
          break;
        }
      }
    }
  });
  return sweeps;
}

} // namespace tpc
