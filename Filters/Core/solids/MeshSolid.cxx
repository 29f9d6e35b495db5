#include "MeshSolid.h"

#include "BucketStarts.h"
#include "ExactPredicates.h"
#include "GridIndex.h"
#include "MeshEdges.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tpc
{

bool WithinTrustedMeshRange(const Box3& bounds)
{
  return bounds.Magnitude() <= LargestTrustedMeshCoordinate && bounds.Diagonal() >= SmallestTrustedMeshDiagonal;
}

MeshSolid::MeshSolid(
  std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles, const ParallelFor& parallelFor)
  : Vertices(std::move(points))
  , Faces(std::move(triangles))
{
  this->Neighbours.assign(this->Faces.size(), { NoTriangle, NoTriangle, NoTriangle });
  std::vector<EdgeUse> uses;
  BuildEdgeTable(this->Faces.data(), this->Faces.size(), uses, parallelFor);
  ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    if (count == 2)
    {
      const EdgeUse &p = uses[first], &q = uses[first + 1];
      this->Neighbours[p.Triangle][p.Corner] = q.Triangle;
      this->Neighbours[q.Triangle][q.Corner] = p.Triangle;
    }
  });
  this->Index(parallelFor);
}

MeshSolid::MeshSolid(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles,
  std::vector<std::array<std::uint32_t, 3>> neighbours, const ParallelFor& parallelFor)
  : Vertices(std::move(points))
  , Faces(std::move(triangles))
  , Neighbours(std::move(neighbours))
{
  if (this->Neighbours.size() != this->Faces.size())
  {
    *this = MeshSolid(std::move(this->Vertices), std::move(this->Faces), parallelFor);
    return;
  }
  this->Index(parallelFor);
}

void MeshSolid::Index(const ParallelFor& parallelFor)
{
  this->Closed = std::all_of(this->Neighbours.begin(), this->Neighbours.end(), [](const auto& across) {
    return across[0] != NoTriangle && across[1] != NoTriangle && across[2] != NoTriangle;
  });
  this->Normals.resize_for_overwrite(this->Faces.size());
  this->AxisFacing.resize_for_overwrite(this->Faces.size());
  this->FaceBoxes.resize_for_overwrite(this->Faces.size());
  parallelFor(this->Faces.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      const Vec3& a = this->Vertex(static_cast<std::uint32_t>(t), 0);
      const Vec3& b = this->Vertex(static_cast<std::uint32_t>(t), 1);
      const Vec3& c = this->Vertex(static_cast<std::uint32_t>(t), 2);
      this->Normals[t] = Normalized(Cross(b - a, c - a));
      for (int axis = 0; axis < 3; ++axis)
      {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        this->AxisFacing[t][axis] = static_cast<std::int8_t>(Orient2D(a[u], a[v], b[u], b[v], c[u], c[v]));
      }
      Box3& box = this->FaceBoxes[t];
      for (int k = 0; k < 3; ++k)
      {
        box.lo[k] = std::min({ a[k], b[k], c[k] });
        box.hi[k] = std::max({ a[k], b[k], c[k] });
      }
    }
  });
  this->Box = { { HUGE_VAL, HUGE_VAL, HUGE_VAL }, { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (const Box3& b : this->FaceBoxes)
  {
    for (int a = 0; a < 3; ++a)
    {
      this->Box.lo[a] = std::min(this->Box.lo[a], b.lo[a]);
      this->Box.hi[a] = std::max(this->Box.hi[a], b.hi[a]);
    }
  }
  if (this->Faces.empty())
  {
    this->Box = {};
    return;
  }
  // Ray-casting grid over (y, z): about two triangles per cell.
  const int n = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(this->Faces.size()) / 2.0)));
  for (int k = 0; k < 2; ++k)
  {
    const int axis = k + 1;
    this->GridSize[k] = n;
    this->GridOrigin[k] = this->Box.lo[axis];
    const double extent = this->Box.hi[axis] - this->Box.lo[axis];
    this->GridStep[k] = extent > 0.0 ? extent / n : 1.0;
  }
  // Each triangle's columns, y0 y1 z0 z1 (in parallel: the floors were most
  // of the grid's build), then entered by a counting sort.
  ReleasableArray<std::array<int, 4>> columns;
  columns.resize_for_overwrite(this->Faces.size());
  const double wy = 1e-9 * this->GridStep[0], wz = 1e-9 * this->GridStep[1];
  parallelFor(this->Faces.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      // Slightly widened: a point on a cell border must find the triangle.
      const Box3& b = this->FaceBoxes[t];
      columns[t] = { this->GridColumn(0, b.lo[1] - wy), this->GridColumn(0, b.hi[1] + wy),
        this->GridColumn(1, b.lo[2] - wz), this->GridColumn(1, b.hi[2] + wz) };
    }
  });
  // (A counting sort, BucketStarts.h.)
  this->GridStart.assign(static_cast<std::size_t>(n) * n + 1, 0);
  for (int pass = 0; pass < 2; ++pass)
  {
    for (std::size_t t = 0; t < this->Faces.size(); ++t)
    {
      const auto [y0, y1, z0, z1] = columns[t];
      for (int y = y0; y <= y1; ++y)
      {
        for (int z = z0; z <= z1; ++z)
        {
          const std::size_t cell = static_cast<std::size_t>(y) * n + z;
          if (pass == 0)
          {
            ++this->GridStart[cell + 1];
          }
          else
          {
            this->GridTriangles[this->GridStart[cell]++] = static_cast<std::uint32_t>(t);
          }
        }
      }
    }
    if (pass == 0)
    {
      std::partial_sum(this->GridStart.begin(), this->GridStart.end(), this->GridStart.begin());
      this->GridTriangles.resize(this->GridStart.back());
    }
  }
  RestoreBucketStarts(this->GridStart);
}

bool MeshSolid::Crosses(std::uint32_t t, const Vec3& a, const Vec3* b, int axis, bool backward) const
{
  // Every query point q stands for q + (eps, eps^2, eps^3), one symbolic
  // perturbation shared by all queries, so every answer is about the same
  // perturbed solid and no query point lies on the surface.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Vec3& A = this->Vertex(t, 0);
  const Vec3& B = this->Vertex(t, 1);
  const Vec3& C = this->Vertex(t, 2);
  const int o = this->AxisFacing[t][axis];
  if (o == 0)
  {
    return false; // parallel to the segment: the perturbed segment misses it
  }
  // Side of edge e0-e1 on which the perturbed trace of the segment lies:
  // Orient2D(e0, e1, q + d) = s + (e1_u - e0_u) d_v - (e1_v - e0_v) d_u,
  // decided by the lowest power of eps when s = 0. Never 0.
  auto side = [&](const Vec3& e0, const Vec3& e1) {
    const int s = Orient2D(e0[u], e0[v], e1[u], e1[v], a[u], a[v]);
    if (s != 0)
    {
      return s;
    }
    const double du = e1[u] - e0[u], dv = e1[v] - e0[v];
    const double first = u < v ? -dv : du, second = u < v ? du : -dv;
    return first != 0.0 ? (first > 0.0 ? 1 : -1) : (second > 0.0 ? 1 : -1);
  };
  if (side(A, B) != o || side(B, C) != o || side(C, A) != o)
  {
    return false;
  }
  // Inner side (behind the triangle): Orient3D > 0. For a point on the
  // plane, n . (A - q - d) = -(n_x eps + n_y eps^2 + n_z eps^3) decides.
  auto inner = [&](const Vec3& q) {
    const int s = Orient3D(A, B, C, q);
    if (s != 0)
    {
      return s > 0;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int nk = this->AxisFacing[t][k]; // sign of n_k
      if (nk != 0)
      {
        return nk < 0;
      }
    }
    return false;
  };
  // Far along +axis the inner side is where the normal's axis component is
  // negative (o < 0), far along -axis where it is positive: the line meets
  // the plane within the triangle, which the side tests found it crosses.
  return inner(a) != (b ? inner(*b) : backward ? o > 0 : o < 0);
}

int MeshSolid::GridColumn(int k, double coordinate) const
{
  // (Monotone in the coordinate: floating-point subtraction, then
  // ClampedGridIndex, never reorder two coordinates.)
  return ClampedGridIndex(coordinate - this->GridOrigin[k], this->GridStep[k], this->GridSize[k]);
}

std::size_t MeshSolid::RayCell(const Vec3& p) const
{
  return static_cast<std::size_t>(this->GridColumn(0, p[1])) * this->GridSize[1] + this->GridColumn(1, p[2]);
}

bool MeshSolid::IsInside(const Vec3& p) const
{
  // Along x to the nearer side of the mesh's box: the same parity as the
  // other way (CrossingsAlongX), past half as many triangles of the column
  // on average.
  // (A closed mesh only - every edge between two triangles: a line crosses
  // it an even number of times. An open one, rejected as an input but
  // oriented first, keeps the ray along +x.)
  const bool backward = this->Closed && p[0] - this->Box.lo[0] < this->Box.hi[0] - p[0];
  return (this->CrossingsAlongX(p, [](std::uint32_t) { return true; }, backward) & 1) != 0;
}

template <typename Crossed>
void MeshSolid::ForEachCrossing(
  const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles, const Crossed& crossed) const
{
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  for (const std::uint32_t t : triangles)
  {
    const Box3& box = this->FaceBoxes[t];
    if (box.hi[axis] < a[axis] || box.lo[axis] > b[axis] || a[u] < box.lo[u] || a[u] > box.hi[u] ||
      a[v] < box.lo[v] || a[v] > box.hi[v])
    {
      continue;
    }
    if (this->Crosses(t, a, &b, axis))
    {
      crossed(t);
    }
  }
}

int MeshSolid::CountCrossings(
  const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles) const
{
  int crossings = 0;
  this->ForEachCrossing(a, b, axis, triangles, [&crossings](std::uint32_t) { ++crossings; });
  return crossings;
}

bool MeshSolid::PlaneCrossing(std::uint32_t t, const Vec3& a, const Vec3& b, int axis, double& coordinate) const
{
  const Vec3& p0 = this->Vertex(t, 0);
  const Vec3 n = Cross(this->Vertex(t, 1) - p0, this->Vertex(t, 2) - p0);
  const double along = n[axis] * (b[axis] - a[axis]);
  const double s = along != 0.0 ? Dot(n, p0 - a) / along : -1.0;
  if (!(s >= 0.0 && s <= 1.0))
  {
    return false; // the segment lies in the plane (decided by the perturbation), or rounding put it outside
  }
  coordinate = a[axis] + s * (b[axis] - a[axis]);
  return true;
}

bool MeshSolid::CrossingPoint(
  const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles, Vec3& point, std::uint32_t* crossed) const
{
  int crossings = 0;
  std::uint32_t hit = 0;
  this->ForEachCrossing(a, b, axis, triangles, [&](std::uint32_t t) {
    ++crossings;
    hit = t;
  });
  double coordinate = 0.0;
  if (crossings != 1 || !this->PlaneCrossing(hit, a, b, axis, coordinate))
  {
    return false;
  }
  point = a;
  point[axis] = coordinate;
  if (crossed)
  {
    *crossed = hit;
  }
  return true;
}

bool MeshSolid::CrossingCoordinates(
  const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles, std::vector<double>& coordinates) const
{
  bool placed = true;
  this->ForEachCrossing(a, b, axis, triangles, [&](std::uint32_t t) {
    double coordinate = 0.0;
    placed = placed && this->PlaneCrossing(t, a, b, axis, coordinate);
    if (placed)
    {
      coordinates.push_back(coordinate);
    }
  });
  return placed;
}

namespace
{
/// The index of the lowest set bit of a nonzero word.
int LowestBit(std::uint64_t bits)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(bits);
#else
  int k = 0;
  for (; (bits & 1) == 0; bits >>= 1)
  {
    ++k;
  }
  return k;
#endif
}

/// Conservative separating-axis test: reports overlap unless a separating
/// axis is found with a margin well above rounding error.
bool TriangleBoxOverlap(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Box3& box)
{
  const Vec3 c = box.Center();
  Vec3 h;
  double scale = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    h[a] = 0.5 * (box.hi[a] - box.lo[a]);
    scale = std::max({ scale, std::fabs(c[a]) + h[a], std::fabs(p0[a]), std::fabs(p1[a]), std::fabs(p2[a]) });
  }
  const double slack = 1e-12 * scale;
  const Vec3 v[3] = { p0 - c, p1 - c, p2 - c };
  // Box axes.
  for (int a = 0; a < 3; ++a)
  {
    const double lo = std::min({ v[0][a], v[1][a], v[2][a] });
    const double hi = std::max({ v[0][a], v[1][a], v[2][a] });
    if (lo > h[a] + slack || hi < -h[a] - slack)
    {
      return false;
    }
  }
  // A side of the triangle passing through the box (the common case where
  // neither holds a corner of the other, cells being about the triangles'
  // size): they meet, which no axis below could deny.
  if (box.MeetsSegment(p0, p1) || box.MeetsSegment(p1, p2) || box.MeetsSegment(p2, p0))
  {
    return true;
  }
  const Vec3 e[3] = { v[1] - v[0], v[2] - v[1], v[0] - v[2] };
  auto separated = [&](const Vec3& axis) {
    const double len = std::fabs(axis[0]) + std::fabs(axis[1]) + std::fabs(axis[2]);
    if (len == 0.0)
    {
      return false;
    }
    const double d0 = Dot(axis, v[0]), d1 = Dot(axis, v[1]), d2 = Dot(axis, v[2]);
    const double r = h[0] * std::fabs(axis[0]) + h[1] * std::fabs(axis[1]) + h[2] * std::fabs(axis[2]);
    const double margin = r + 1e-9 * (r + len * scale) + slack * len;
    return std::min({ d0, d1, d2 }) > margin || std::max({ d0, d1, d2 }) < -margin;
  };
  // Triangle plane.
  if (separated(Cross(e[0], e[1])))
  {
    return false;
  }
  // Edge cross products.
  for (int i = 0; i < 3; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      Vec3 unit;
      unit[a] = 1.0;
      if (separated(Cross(unit, e[i])))
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace

void MeshSolid::Overlapping(const Box3& box, const TriangleList& candidates, TriangleList& out) const
{
  out.clear();
  for (const std::uint32_t t : candidates)
  {
    const Box3& b = this->FaceBoxes[t];
    bool apart = false, within = true;
    for (int a = 0; a < 3 && !apart; ++a)
    {
      apart = b.lo[a] > box.hi[a] || b.hi[a] < box.lo[a];
      within = within && b.lo[a] >= box.lo[a] && b.hi[a] <= box.hi[a];
    }
    // A triangle whose box lies in the cell, or with a vertex in it, meets it
    // (the common cases while cells are not much smaller than triangles): no
    // separating-axis test needed.
    if (!apart &&
      (within || box.Contains(this->Vertex(t, 0)) || box.Contains(this->Vertex(t, 1)) ||
        box.Contains(this->Vertex(t, 2)) ||
        TriangleBoxOverlap(this->Vertex(t, 0), this->Vertex(t, 1), this->Vertex(t, 2), box)))
    {
      out.push_back(t);
    }
  }
}

TriangleList MeshSolid::Overlapping(const Box3& box) const
{
  // The candidates from the ray-casting grid's columns under the box's
  // (y, z) extent: a triangle meeting the box has a point (y, z) in both its
  // box and the query's, and the column holding that point is among those
  // it was entered in (its box's, widened) and among the query's (the column
  // of a coordinate is monotone in it). Gathered in a bit per triangle and
  // read back in order, they give the list a scan of every triangle would
  // (cells of a mesh and quadric scene bounded as one quadric prune the
  // scene's whole expression: that scan was half of armadillo-cavities' run
  // at 1/128).
  TriangleList candidates, out;
  if (this->Faces.empty())
  {
    return out;
  }
  thread_local std::vector<std::uint64_t> listed;
  listed.assign((this->Faces.size() + 63) / 64, 0);
  const int y0 = this->GridColumn(0, box.lo[1]), y1 = this->GridColumn(0, box.hi[1]);
  const int z0 = this->GridColumn(1, box.lo[2]), z1 = this->GridColumn(1, box.hi[2]);
  for (int y = y0; y <= y1; ++y)
  {
    for (int z = z0; z <= z1; ++z)
    {
      const std::size_t cell = static_cast<std::size_t>(y) * this->GridSize[1] + z;
      for (std::uint32_t i = this->GridStart[cell]; i < this->GridStart[cell + 1]; ++i)
      {
        const std::uint32_t t = this->GridTriangles[i];
        listed[t / 64] |= std::uint64_t{ 1 } << (t % 64);
      }
    }
  }
  for (std::size_t w = 0; w < listed.size(); ++w)
  {
    for (std::uint64_t bits = listed[w]; bits != 0; bits &= bits - 1)
    {
      candidates.push_back(static_cast<std::uint32_t>(64 * w + static_cast<std::size_t>(LowestBit(bits))));
    }
  }
  this->Overlapping(box, candidates, out);
  return out;
}

namespace
{
/// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    return a + ab * (d1 / (d1 - d3));
  }
  const Vec3 cp = p - c;
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    return a + ac * (d2 / (d2 - d6));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}
} // namespace

double MeshSolid::ApproximateSignedDistance(
  const Vec3& p, const TriangleList& triangles, std::uint32_t* nearest) const
{
  double best = HUGE_VAL;
  std::uint32_t bestT = triangles.empty() ? 0 : triangles.front();
  Vec3 bestQ;
  for (const std::uint32_t t : triangles)
  {
    const Vec3 q = ClosestPointOnTriangle(p, this->Vertex(t, 0), this->Vertex(t, 1), this->Vertex(t, 2));
    const double d = Dot(p - q, p - q);
    if (d < best)
    {
      best = d;
      bestT = t;
      bestQ = q;
    }
  }
  if (nearest)
  {
    *nearest = bestT;
  }
  if (triangles.empty())
  {
    return HUGE_VAL;
  }
  const double d = std::sqrt(best);
  return Dot(p - bestQ, Cross(this->Vertex(bestT, 1) - this->Vertex(bestT, 0),
                          this->Vertex(bestT, 2) - this->Vertex(bestT, 0))) < 0.0
    ? -d
    : d;
}

} // namespace tpc
