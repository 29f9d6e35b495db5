#include "SelfIntersection.h"

#include "BucketStarts.h"
#include "EmbeddedStars.h"
#include "ExactPredicates.h"
#include "GridIndex.h"
#include "MeshSolid.h"
#include "TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

namespace tpc
{
namespace
{
/// A projection (dropping one axis) in which the triangle keeps its area; -1
/// for a degenerate triangle.
int ProjectionAxis(const Vec3& a, const Vec3& b, const Vec3& c)
{
  for (int k = 0; k < 3; ++k)
  {
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    if (Orient2D(a[u], a[v], b[u], b[v], c[u], c[v]) != 0)
    {
      return k;
    }
  }
  return -1;
}

struct Projected
{
  double U, V;
};

Projected Project(const Vec3& p, int k)
{
  return { p[(k + 1) % 3], p[(k + 2) % 3] };
}

int O2(const Projected& a, const Projected& b, const Projected& c)
{
  return Orient2D(a.U, a.V, b.U, b.V, c.U, c.V);
}

/// Closed 2-D segments ab and cd intersect.
bool SegmentsMeet2D(const Projected& a, const Projected& b, const Projected& c, const Projected& d)
{
  const int o1 = O2(a, b, c), o2 = O2(a, b, d), o3 = O2(c, d, a), o4 = O2(c, d, b);
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0 && !(o1 == 0 && o2 == 0))
  {
    return true;
  }
  auto onSegment = [](const Projected& p, const Projected& q, const Projected& r) {
    // r collinear with pq: within its bounding box
    return std::min(p.U, q.U) <= r.U && r.U <= std::max(p.U, q.U) && std::min(p.V, q.V) <= r.V &&
      r.V <= std::max(p.V, q.V);
  };
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
    (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

/// Closed point-in-triangle in 2-D (triangle of either orientation).
bool PointInTriangle2D(const Projected& p, const Projected& a, const Projected& b, const Projected& c)
{
  const int o = O2(a, b, c);
  const int s1 = O2(a, b, p), s2 = O2(b, c, p), s3 = O2(c, a, p);
  return s1 * o >= 0 && s2 * o >= 0 && s3 * o >= 0;
}

/// Two coplanar closed triangles overlap (k: a projection keeping their area).
bool CoplanarTrianglesMeet(const Vec3 t1[3], const Vec3 t2[3], int k)
{
  Projected p[3], q[3];
  for (int i = 0; i < 3; ++i)
  {
    p[i] = Project(t1[i], k);
    q[i] = Project(t2[i], k);
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (SegmentsMeet2D(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3]))
      {
        return true;
      }
    }
  }
  return PointInTriangle2D(p[0], q[0], q[1], q[2]) || PointInTriangle2D(q[0], p[0], p[1], p[2]);
}
} // namespace

bool TriangleIsDegenerate(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return ProjectionAxis(a, b, c) < 0;
}

namespace
{
/// SegmentMeetsTriangle, with p's and q's sides of abc's plane known: `sp` =
/// Orient3D(a, b, c, p), `sq` = Orient3D(a, b, c, q) (the triangle tests have
/// them already: every side is computed once).
bool SegmentMeetsTriangleWithSides(
  const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, int sp, int sq)
{
  if (sp != 0 && sp == sq)
  {
    return false;
  }
  if (sp == 0 && sq == 0)
  {
    const int k = ProjectionAxis(a, b, c);
    if (k < 0)
    {
      return false;
    }
    const Projected P = Project(p, k), Q = Project(q, k), A = Project(a, k), B = Project(b, k), C = Project(c, k);
    return PointInTriangle2D(P, A, B, C) || PointInTriangle2D(Q, A, B, C) || SegmentsMeet2D(P, Q, A, B) ||
      SegmentsMeet2D(P, Q, B, C) || SegmentsMeet2D(P, Q, C, A);
  }
  // The segment reaches the plane: it meets the triangle iff it passes on the
  // same side of (or through) all three edges.
  const int e1 = Orient3D(p, q, a, b), e2 = Orient3D(p, q, b, c), e3 = Orient3D(p, q, c, a);
  return (e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0);
}
} // namespace

bool SegmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c)
{
  return SegmentMeetsTriangleWithSides(p, q, a, b, c, Orient3D(a, b, c, p), Orient3D(a, b, c, q));
}

bool TrianglesIntersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
  const Vec3& f)
{
  const int s1 = Orient3D(a, b, c, d), s2 = Orient3D(a, b, c, e), s3 = Orient3D(a, b, c, f);
  if ((s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0))
  {
    return false;
  }
  if (s1 == 0 && s2 == 0 && s3 == 0)
  {
    const int k = ProjectionAxis(a, b, c);
    const Vec3 t1[3] = { a, b, c }, t2[3] = { d, e, f };
    return k >= 0 && CoplanarTrianglesMeet(t1, t2, k);
  }
  const int r1 = Orient3D(d, e, f, a), r2 = Orient3D(d, e, f, b), r3 = Orient3D(d, e, f, c);
  if ((r1 > 0 && r2 > 0 && r3 > 0) || (r1 < 0 && r2 < 0 && r3 < 0))
  {
    return false;
  }
  // Non-coplanar triangles meet iff an edge of one meets the other (the
  // edges' ends' sides are the r's and s's).
  return SegmentMeetsTriangleWithSides(a, b, d, e, f, r1, r2) || SegmentMeetsTriangleWithSides(b, c, d, e, f, r2, r3) ||
    SegmentMeetsTriangleWithSides(c, a, d, e, f, r3, r1) || SegmentMeetsTriangleWithSides(d, e, a, b, c, s1, s2) ||
    SegmentMeetsTriangleWithSides(e, f, a, b, c, s2, s3) || SegmentMeetsTriangleWithSides(f, d, a, b, c, s3, s1);
}

namespace
{
/// The closed 2-D triangles (a, b, c) and (d, e, f) are apart: an edge line
/// of one has the other strictly on its outer side.
bool ApartIn2D(const Projected t1[3], const Projected t2[3])
{
  auto separates = [](const Projected t[3], const Projected u[3]) {
    const int o = O2(t[0], t[1], t[2]);
    for (int i = 0; i < 3; ++i)
    {
      const Projected &p = t[i], &q = t[(i + 1) % 3];
      if (O2(p, q, u[0]) * o < 0 && O2(p, q, u[1]) * o < 0 && O2(p, q, u[2]) * o < 0)
      {
        return true;
      }
    }
    return false;
  };
  return separates(t1, t2) || separates(t2, t1);
}

/// A fast, sound proof that two triangles meet properly, by a projection
/// along an axis that keeps both of their areas (ProjectionAxis): it is
/// injective on each, so a point the triangles share beyond what they share
/// by index would project onto a point their projections share beyond the
/// projection of that. Proper in projection (apart; on opposite sides of
/// the shared edge; separated by a line through the shared vertex) is then
/// proper in space. Nearly coplanar neighbours - patches of flat parts of a
/// surface - are decided this way by well-conditioned 2-D orientations,
/// where the 3-D predicates would need their exact stage. False: no proof
/// (the full test decides).
bool ProperInProjection(const Vec3* P, const std::array<std::uint32_t, 3>& t1,
  const std::array<std::uint32_t, 3>& t2, int shared)
{
  const Vec3 &a = P[t1[0]], &b = P[t1[1]], &c = P[t1[2]], &d = P[t2[0]], &e = P[t2[1]], &f = P[t2[2]];
  const Vec3 n = Cross(b - a, c - a);
  int k = 0;
  for (int i = 1; i < 3; ++i)
  {
    k = std::fabs(n[i]) > std::fabs(n[k]) ? i : k;
  }
  const Projected p[3] = { Project(a, k), Project(b, k), Project(c, k) };
  const Projected q[3] = { Project(d, k), Project(e, k), Project(f, k) };
  if (O2(p[0], p[1], p[2]) == 0 || O2(q[0], q[1], q[2]) == 0)
  {
    return false; // a projection without area: not injective
  }
  if (shared == 0)
  {
    return ApartIn2D(p, q);
  }
  // The shared vertices' positions in each triangle.
  int in1[3] = { -1, -1, -1 }, in2[3] = { -1, -1, -1 };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (t1[i] == t2[j])
      {
        in1[i] = j;
        in2[j] = i;
      }
    }
  }
  if (shared == 2)
  {
    // Opposite vertices strictly on opposite sides of the shared edge.
    const int o1 = in1[0] < 0 ? 0 : (in1[1] < 0 ? 1 : 2), o2 = in2[0] < 0 ? 0 : (in2[1] < 0 ? 1 : 2);
    const Projected &u = p[(o1 + 1) % 3], &w = p[(o1 + 2) % 3];
    return O2(u, w, p[o1]) * O2(u, w, q[o2]) < 0;
  }
  // One shared vertex v: the two (closed, convex) projections meet only at v
  // iff their angles at v share no direction.
  const int i1 = in1[0] >= 0 ? 0 : (in1[1] >= 0 ? 1 : 2), i2 = in1[i1];
  const Projected &v = p[i1], &a1 = p[(i1 + 1) % 3], &b1 = p[(i1 + 2) % 3];
  const Projected &a2 = q[(i2 + 1) % 3], &b2 = q[(i2 + 2) % 3];
  const int s1 = O2(v, a1, b1), s2 = O2(v, a2, b2);
  // Direction toward x within the closed angle (from, to) of orientation s.
  auto within = [&](const Projected& from, const Projected& to, int s, const Projected& x) {
    return O2(v, from, x) * s >= 0 && O2(v, x, to) * s >= 0;
  };
  return !within(a1, b1, s1, a2) && !within(a1, b1, s1, b2) && !within(a2, b2, s2, a1) && !within(a2, b2, s2, b1);
}
} // namespace

namespace
{
/// Triangles t1 and t2 share exactly the vertex t1[i1] = t2[i2]: do they meet
/// elsewhere?
bool MeetBeyondSharedVertex(const Vec3* P, const Triangle& t1, const Triangle& t2, int i1, int i2)
{
  const Vec3 &a = P[t1[0]], &b = P[t1[1]], &c = P[t1[2]], &d = P[t2[0]], &e = P[t2[1]], &f = P[t2[2]];
  // Only the shared vertex may be common: the edge opposite it in each
  // triangle must miss the other triangle, and coplanar triangles must not
  // overlap beyond the vertex.
  const Vec3 &o1a = P[t1[(i1 + 1) % 3]], &o1b = P[t1[(i1 + 2) % 3]];
  const Vec3 &o2a = P[t2[(i2 + 1) % 3]], &o2b = P[t2[(i2 + 2) % 3]];
  if (SegmentMeetsTriangle(o1a, o1b, d, e, f))
  {
    return true;
  }
  const int s2a = Orient3D(a, b, c, o2a), s2b = Orient3D(a, b, c, o2b);
  if (SegmentMeetsTriangleWithSides(o2a, o2b, a, b, c, s2a, s2b))
  {
    return true;
  }
  if (s2a == 0 && s2b == 0)
  {
    // Coplanar fan around the shared vertex: overlap iff a side edge of one
    // enters the other (the opposite edges were tested above).
    const int k = ProjectionAxis(a, b, c);
    if (k >= 0)
    {
      const Projected v = Project(P[t1[i1]], k);
      const Projected A = Project(o1a, k), B = Project(o1b, k), C = Project(o2a, k), D = Project(o2b, k);
      const int oa = O2(v, A, B);
      // Is a direction toward C or D strictly inside angle (A, B) at v, or vice versa?
      auto inside = [&](const Projected& x, const Projected& y, const Projected& z, int o) {
        return O2(v, x, z) * o > 0 && O2(v, z, y) * o > 0;
      };
      const int ob = O2(v, C, D);
      return inside(A, B, C, oa) || inside(A, B, D, oa) || inside(C, D, A, ob) || inside(C, D, B, ob);
    }
  }
  return false;
}

/// Triangles t1 and t2 share exactly one edge: are they folded flat onto
/// each other?
bool FoldedOntoSharedEdge(const Vec3* P, const Triangle& t1, const Triangle& t2)
{
  const Vec3 &a = P[t1[0]], &b = P[t1[1]], &c = P[t1[2]];
  int o1 = -1, o2 = -1;
  for (int i = 0; i < 3; ++i)
  {
    if (t1[i] != t2[0] && t1[i] != t2[1] && t1[i] != t2[2])
    {
      o1 = i;
    }
    if (t2[i] != t1[0] && t2[i] != t1[1] && t2[i] != t1[2])
    {
      o2 = i;
    }
  }
  const Vec3& p = P[t2[o2]];
  if (Orient3D(a, b, c, p) != 0)
  {
    return false;
  }
  const int k = ProjectionAxis(a, b, c);
  if (k < 0)
  {
    return false;
  }
  const Vec3& s0 = P[t1[(o1 + 1) % 3]];
  const Vec3& s1 = P[t1[(o1 + 2) % 3]];
  const Projected S0 = Project(s0, k), S1 = Project(s1, k), Q = Project(P[t1[o1]], k), R = Project(p, k);
  return O2(S0, S1, Q) * O2(S0, S1, R) > 0; // both on the same side of the shared edge
}
} // namespace

bool TrianglesMeetImproperly(const Vec3* P, const Triangle& t1, const Triangle& t2)
{
  int shared = 0, i1 = -1, i2 = -1;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (t1[i] == t2[j])
      {
        ++shared;
        i1 = i;
        i2 = j;
      }
    }
  }
  if (shared < 3 && ProperInProjection(P, t1, t2, shared))
  {
    return false;
  }
  switch (shared)
  {
    case 0:
      return TrianglesIntersect(P[t1[0]], P[t1[1]], P[t1[2]], P[t2[0]], P[t2[1]], P[t2[2]]);
    case 1:
      return MeetBeyondSharedVertex(P, t1, t2, i1, i2);
    case 2:
      return FoldedOntoSharedEdge(P, t1, t2);
    default:
      return true; // identical triangles
  }
}

namespace
{
/// The bins of a uniform grid over triangle boxes: cells about twice the
/// median triangle size (a box's largest width), at most about 8 n of them.
/// (The median, not the mean: a CAD part's few long slivers made the mean's
/// cells hold many of its small triangles, every pair of them tried; with
/// the median the turbine's and couplingdown's repair and check take 7 % and
/// 17 % fewer instructions, reading the file included, armadillo's, of even
/// triangles, 0.5 % more.)
struct BinGrid
{
  Box3 All{ { HUGE_VAL, HUGE_VAL, HUGE_VAL }, { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  double Cell = 0.0;
  int Dims[3] = { 1, 1, 1 };

  BinGrid(const ReleasableArray<Box3>& boxes)
  {
    std::vector<double> sizes(boxes.size());
    for (std::size_t t = 0; t < boxes.size(); ++t)
    {
      const Box3& b = boxes[t];
      for (int a = 0; a < 3; ++a)
      {
        this->All.lo[a] = std::min(this->All.lo[a], b.lo[a]);
        this->All.hi[a] = std::max(this->All.hi[a], b.hi[a]);
      }
      const double size = std::max({ b.Width(0), b.Width(1), b.Width(2) });
      sizes[t] = std::isnan(size) ? 0.0 : size; // (a strict weak order for the median)
    }
    const auto middle = sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2);
    std::nth_element(sizes.begin(), middle, sizes.end());
    this->Cell = std::max(2.0 * *middle, 1e-300);
    for (;;)
    {
      double cells = 1.0;
      for (int a = 0; a < 3; ++a)
      {
        this->Dims[a] = std::max(1, static_cast<int>(std::ceil(this->All.Width(a) / this->Cell)));
        cells *= this->Dims[a];
      }
      if (cells <= 8.0 * static_cast<double>(boxes.size()) + 64.0)
      {
        break;
      }
      this->Cell *= 1.5;
    }
  }
  int Index(int a, double x) const
  {
    return ClampedGridIndex(x - this->All.lo[a], this->Cell, this->Dims[a]);
  }
  std::uint64_t Key(int x, int y, int z) const
  {
    return (static_cast<std::uint64_t>(x) * this->Dims[1] + y) * this->Dims[2] + z;
  }
  /// The bin indices (x, y, z) of key k.
  std::array<int, 3> Coordinates(std::uint64_t k) const
  {
    const auto z = static_cast<int>(k % static_cast<std::uint64_t>(this->Dims[2]));
    k /= static_cast<std::uint64_t>(this->Dims[2]);
    return { static_cast<int>(k / static_cast<std::uint64_t>(this->Dims[1])),
      static_cast<int>(k % static_cast<std::uint64_t>(this->Dims[1])), z };
  }
  /// The bins triangle box `b` meets, as index ranges per axis.
  void BinRange(const Box3& b, int lo[3], int hi[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = this->Index(a, b.lo[a]);
      hi[a] = this->Index(a, b.hi[a]);
    }
  }
  /// Number of bins.
  std::size_t Bins() const
  {
    return static_cast<std::size_t>(this->Dims[0]) * static_cast<std::size_t>(this->Dims[1]) *
      static_cast<std::size_t>(this->Dims[2]);
  }
};

/// The triangles of each bin of a BinGrid, every bin each triangle's box
/// meets: the triangles of bin k are Triangles[Start[k]] to
/// Triangles[Start[k + 1] - 1], in increasing order (a counting sort by bin:
/// linear, where sorting (bin, triangle) pairs was a tenth of the check).
/// Lower[t]: the bin indices of triangle t's box's lower corner.
struct BinnedTriangles
{
  std::vector<std::size_t> Start;
  ReleasableArray<std::uint32_t> Triangles;
  ReleasableArray<std::array<int, 3>> Lower;

  BinnedTriangles(const BinGrid& grid, const ReleasableArray<Box3>& boxes, const ParallelFor& parallelFor)
    : Start(grid.Bins() + 1, 0)
  {
    // (Every value below is written before it is read: resize_for_overwrite.)
    ReleasableArray<std::array<int, 3>> upper;
    this->Lower.resize_for_overwrite(boxes.size());
    upper.resize_for_overwrite(boxes.size());
    parallelFor(boxes.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
      {
        grid.BinRange(boxes[t], this->Lower[t].data(), upper[t].data());
      }
    });
    const auto forEachBin = [&](std::size_t t, const auto& visit) {
      const std::array<int, 3>&lo = this->Lower[t], &hi = upper[t];
      for (int x = lo[0]; x <= hi[0]; ++x)
      {
        for (int y = lo[1]; y <= hi[1]; ++y)
        {
          for (int z = lo[2]; z <= hi[2]; ++z)
          {
            visit(grid.Key(x, y, z));
          }
        }
      }
    };
    for (std::size_t t = 0; t < boxes.size(); ++t)
    {
      forEachBin(t, [&](std::uint64_t k) { ++this->Start[k + 1]; });
    }
    std::partial_sum(this->Start.begin(), this->Start.end(), this->Start.begin());
    this->Triangles.resize_for_overwrite(this->Start.back());
    // (Filled from the starts themselves, BucketStarts.h: a copy of them
    // was a third of the pages the check first touched.)
    for (std::size_t t = 0; t < boxes.size(); ++t)
    {
      forEachBin(t, [&](std::uint64_t k) { this->Triangles[this->Start[k]++] = static_cast<std::uint32_t>(t); });
    }
    RestoreBucketStarts(this->Start);
  }
};

/// How many pairs of triangles `accept` takes, counting at most `limit`,
/// among the candidate pairs - those whose bounding boxes overlap. The boxes
/// are binned by a uniform grid (BinnedTriangles); a pair shares every bin
/// its boxes' intersection meets, and is tried in the first of them only -
/// the bin of the intersection's lower corner, whose index on each axis is
/// the larger of the two boxes' lower indices (Index is monotone) - so no
/// pair is tried twice. The pairs are tried where they are found, bin by bin
/// (a list of them all would be written and read once, and merged on one
/// thread: a quarter of the check on armadillo). Blocks of whole bins, of
/// about as many entries each, are searched in parallel, each counting up to
/// the limit, so the capped sum is min(total, limit) whatever the thread
/// count; blocks run in chunks that report progress, and counting stops once
/// the limit is reached (or on an abort: the count is then partial, and the
/// caller that asked discards it).
template <typename Accept>
std::size_t CountAcceptedPairs(const std::vector<Vec3>& points,
  const std::vector<std::array<std::uint32_t, 3>>& triangles, const ReleasableArray<Box3>* givenBoxes, std::size_t limit,
  const ParallelFor& parallelFor, const ProgressCallback& progress, const Accept& accept)
{
  if (triangles.size() < 2 || limit == 0)
  {
    return 0;
  }
  // (The triangles' boxes: the caller's where it keeps them.)
  ReleasableArray<Box3> ownBoxes;
  if (!givenBoxes)
  {
    ownBoxes.resize_for_overwrite(triangles.size());
    parallelFor(triangles.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
      {
        ownBoxes[t] = TriangleBox(points.data(), triangles[t]);
      }
    });
  }
  const ReleasableArray<Box3>& boxes = givenBoxes ? *givenBoxes : ownBoxes;
  const BinGrid grid(boxes);
  const BinnedTriangles bins(grid, boxes, parallelFor);
  if (progress && progress(0.2))
  {
    return 0;
  }
  // Blocks of whole bins: many more than threads, since the pairs per bin
  // vary widely (dense regions).
  constexpr std::size_t Blocks = 512, BlocksPerChunk = 64;
  const std::size_t binCount = grid.Bins();
  std::vector<std::size_t> blockBin(Blocks + 1, binCount); // (block b: bins blockBin[b] .. blockBin[b + 1] - 1)
  for (std::size_t b = 0; b < Blocks; ++b)
  {
    // The first bin starting at or after the block's share of the entries.
    const std::size_t share = bins.Triangles.size() * b / Blocks;
    blockBin[b] = std::min<std::size_t>(binCount,
      static_cast<std::size_t>(std::lower_bound(bins.Start.begin(), bins.Start.end(), share) - bins.Start.begin()));
  }
  std::vector<std::size_t> found(Blocks, 0);
  std::size_t total = 0;
  ForEachChunk(Blocks, BlocksPerChunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint8_t> startsHere; // (per entry of a bin: the axes it starts on there, below)
    for (std::size_t b = begin; b < end; ++b)
    {
      for (std::size_t k = blockBin[b]; k < blockBin[b + 1] && found[b] < limit; ++k)
      {
        const std::size_t i = bins.Start[k], j = bins.Start[k + 1];
        // Both boxes of a pair in bin k start at or below it on each axis,
        // so k is their first common bin - the larger lower index on every
        // axis - exactly when on each axis one of them starts at k: a bit
        // per axis and entry, and an or per pair, before its boxes are read
        // (the pair loop is a quarter of armadillo's input repair and check;
        // 8 % fewer of its instructions than when both boxes were read and
        // that bin computed for every pair).
        const std::array<int, 3> at = grid.Coordinates(k);
        startsHere.resize(j - i);
        for (std::size_t p = i; p < j; ++p)
        {
          const std::array<int, 3>& lower = bins.Lower[bins.Triangles[p]];
          startsHere[p - i] =
            static_cast<std::uint8_t>((lower[0] == at[0]) | (lower[1] == at[1]) << 1 | (lower[2] == at[2]) << 2);
        }
        for (std::size_t p = i; p < j && found[b] < limit; ++p)
        {
          for (std::size_t q = p + 1; q < j && found[b] < limit; ++q)
          {
            const std::uint32_t t1 = bins.Triangles[p], t2 = bins.Triangles[q]; // (t1 < t2)
            if ((startsHere[p - i] | startsHere[q - i]) == 7 && boxes[t1].Overlaps(boxes[t2]) && accept(t1, t2))
            {
              ++found[b];
            }
          }
        }
      }
    }
  }, [&](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; ++b)
    {
      total += found[b];
    }
    return total >= limit ||
      (progress && progress(0.2 + 0.8 * static_cast<double>(last) / static_cast<double>(Blocks)));
  });
  return std::min(total, limit);
}
} // namespace

namespace
{
/// `given`: the stars proven of these triangles, or null to prove them here.
std::size_t CountImproperPairs(const std::vector<Vec3>& points,
  const std::vector<std::array<std::uint32_t, 3>>& triangles, const ReleasableArray<Box3>* boxes,
  const EmbeddedStars* given, std::size_t limit, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  if (triangles.size() < 2 || limit == 0)
  {
    return 0;
  }
  // Pairs sharing a vertex whose star is proven embedded need no test of
  // their own (EmbeddedStars.h): most candidate pairs are neighbours.
  std::optional<EmbeddedStars> own;
  if (!given)
  {
    own.emplace(points.data(), points.size(), triangles.data(), triangles.size(), parallelFor);
  }
  const EmbeddedStars& stars = given ? *given : *own;
  return CountAcceptedPairs(points, triangles, boxes, limit, parallelFor, progress,
    [&](std::uint32_t t1, std::uint32_t t2) {
      return !stars.ProveProper(triangles[t1], triangles[t2]) &&
        TrianglesMeetImproperly(points.data(), triangles[t1], triangles[t2]);
    });
}
} // namespace

std::size_t CountSelfIntersections(const std::vector<Vec3>& points,
  const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t limit,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  return CountImproperPairs(points, triangles, nullptr, nullptr, limit, parallelFor, progress);
}

std::size_t CountSelfIntersections(const MeshSolid& mesh, const EmbeddedStars& stars, std::size_t limit,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  return CountImproperPairs(
    mesh.Points(), mesh.Triangles(), &mesh.TriangleBoxes(), &stars, limit, parallelFor, progress);
}

std::size_t CountCoincidentFaces(const std::vector<Vec3>& pointsA,
  const std::vector<std::array<std::uint32_t, 3>>& trianglesA, const std::vector<Vec3>& pointsB,
  const std::vector<std::array<std::uint32_t, 3>>& trianglesB, bool facingEachOther, std::size_t limit,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // Both meshes in one list, B's indices after A's.
  std::vector<Vec3> points = pointsA;
  points.insert(points.end(), pointsB.begin(), pointsB.end());
  std::vector<std::array<std::uint32_t, 3>> triangles = trianglesA;
  const auto offset = static_cast<std::uint32_t>(pointsA.size());
  for (const auto& t : trianglesB)
  {
    triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const auto fromA = static_cast<std::uint32_t>(trianglesA.size());
  return CountAcceptedPairs(points, triangles, nullptr, limit, parallelFor, progress,
    [&](std::uint32_t t1, std::uint32_t t2) {
      if ((t1 < fromA) == (t2 < fromA))
      {
        return false; // both from one mesh
      }
      const Vec3 p[3] = { points[triangles[t1][0]], points[triangles[t1][1]], points[triangles[t1][2]] };
      const Vec3 q[3] = { points[triangles[t2][0]], points[triangles[t2][1]], points[triangles[t2][2]] };
      for (const Vec3& v : q)
      {
        if (Orient3D(p[0], p[1], p[2], v) != 0)
        {
          return false;
        }
      }
      // Facing each other: opposite windings in a common projection.
      const int k = ProjectionAxis(p[0], p[1], p[2]);
      const Projected pp[3] = { Project(p[0], k), Project(p[1], k), Project(p[2], k) };
      const Projected qq[3] = { Project(q[0], k), Project(q[1], k), Project(q[2], k) };
      const bool opposite = O2(pp[0], pp[1], pp[2]) * O2(qq[0], qq[1], qq[2]) < 0;
      return opposite == facingEachOther && CoplanarTrianglesMeet(p, q, k);
    });
}

} // namespace tpc
