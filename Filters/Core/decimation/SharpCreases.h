// The input's sharp creases, and whether a collapse keeps them followed by
// the surface's creases (CertifiedDecimation.h, Creases).
//
// A sharp crease is an input edge whose two triangles' normals differ by
// SharpCreaseAngle or more (40 degrees: a crease barely past the output's
// feature angle may bend the output by less at each of two edges - the
// angle the crease tests use). The extraction follows them: every point of
// one lies within the tolerance of an output edge whose triangles bend by
// the feature angle or more (CreaseFollowing.h). A collapse changes the
// output's feature edges only near its star: some are removed (no longer
// there, or no longer bent), others appear. A point x of a sharp crease
// within `reach` of the feature edges before is within `reach` after if its
// nearest one was kept; so only points within `reach` of a removed edge need
// a look, and StaysFollowed decides, for a piece of sharp crease near the
// star, that each of them is within `reach` of the feature edges after, by a
// branch and bound along the piece:
// - the distance to one segment is convex, so over a piece [a, b] it is at
//   most max(d(a), d(b)): min over segments j of that bounds the distance to
//   the feature edges after from above, and a piece within `reach` is done;
// - the distance to a set of segments is 1-Lipschitz, so over the piece it
//   is at least d(m) - |b - a| / 2 at its midpoint m: a piece farther than
//   `reach` from every removed edge needs nothing;
// - an end within `reach` of a removed edge and beyond it from every edge
//   after is a counterexample;
// otherwise the piece is halved, up to a budget (then it fails).
#pragma once

#include "MeshSolid.h"
#include "Vector3.h"

#include <vector>

namespace tpc
{

/// Degrees: input creases at least this sharp stay followed.
constexpr double SharpCreaseAngle = 40.0;

struct EdgeSegment
{
  Vec3 A;
  Vec3 B;
};

/// The edges of `mesh` whose triangles' normals differ by `degrees` or more.
std::vector<EdgeSegment> SharpEdges(const MeshSolid& mesh, double degrees);

/// The distance from p to the nearest of `segments` (+inf when none).
double DistanceToSegments(const Vec3& p, const std::vector<EdgeSegment>& segments);

/// Header: is every point of ab within `reach` of a `removed` edge within
/// `reach` of `after`? At most `budget` pieces examined (then false).
bool StaysFollowed(const Vec3& a, const Vec3& b, const std::vector<EdgeSegment>& removed,
  const std::vector<EdgeSegment>& after, double reach, std::size_t budget = 1024);

} // namespace tpc
