#include "MeshArrangement.h"

#include "ExactPredicates.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tpc
{

ArrangementPoint ArrangementPoint::Vertex(std::uint32_t v)
{
  ArrangementPoint p;
  p.PointKind = Kind::MeshVertex;
  p.A = v;
  return p;
}

ArrangementPoint ArrangementPoint::EdgeOnPlane(std::uint32_t a, std::uint32_t b, int axis, LatticeIndex coordinate)
{
  ArrangementPoint p;
  p.PointKind = Kind::EdgeOnPlane;
  p.A = std::min(a, b);
  p.B = std::max(a, b);
  p.Axis = axis;
  p.Lattice[axis] = coordinate;
  return p;
}

ArrangementPoint ArrangementPoint::TriangleOnLine(std::uint32_t t, int freeAxis, const LatticeIndex lattice[3])
{
  ArrangementPoint p;
  p.PointKind = Kind::TriangleOnLine;
  p.A = t;
  p.Axis = freeAxis;
  for (int a = 0; a < 3; ++a)
  {
    p.Lattice[a] = a == freeAxis ? 0u : lattice[a];
  }
  return p;
}

std::int64_t ArrangementPoint::FixedCoordinate(int axis) const
{
  const bool fixed = (this->PointKind == Kind::EdgeOnPlane && axis == this->Axis) ||
    (this->PointKind == Kind::TriangleOnLine && axis != this->Axis);
  return fixed ? static_cast<std::int64_t>(this->Lattice[axis]) : -1;
}

MeshArrangement::MeshArrangement(const MeshSolid& mesh, const RootGrid& grid)
  : Solid(mesh)
  , Grid(grid)
{
}

namespace
{
int SignOf(double x)
{
  return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0);
}

/// Sign of component k of the normal (B - A) x (C - A), exactly.
int NormalSign(const Vec3& A, const Vec3& B, const Vec3& C, int k)
{
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  return Orient2D(A[u], A[v], B[u], B[v], C[u], C[v]);
}
} // namespace

int MeshArrangement::VertexSide(const Vec3& p, int axis, double c) const
{
  return p[axis] > c ? 1 : -1; // on the plane: p - d is below
}

int MeshArrangement::EdgeSide(const ArrangementPoint& p, int a, double c) const
{
  const int b = p.Axis;
  const Vec3& P = this->Solid.Points()[p.A];
  const Vec3& Q = this->Solid.Points()[p.B];
  const double e = this->Grid.Coordinate(b, p.Lattice[b]);
  const int rise = SignOf(Q[b] - P[b]); // non-zero: the edge crosses the plane x_b = e
  const int d = -Orient2D(P[b], P[a], Q[b], Q[a], e, c);
  if (d != 0)
  {
    return d * rise;
  }
  const int slope = SignOf(Q[a] - P[a]) * rise;
  return b < a && slope != 0 ? slope : -1;
}

int MeshArrangement::TriangleSide(const ArrangementPoint& p, int a, double c) const
{
  const std::uint32_t t = p.A;
  const Vec3 &A = this->Solid.Vertex(t, 0), &B = this->Solid.Vertex(t, 1), &C = this->Solid.Vertex(t, 2);
  Vec3 Z;
  for (int k = 0; k < 3; ++k)
  {
    Z[k] = k == a ? c : this->Grid.Coordinate(k, p.Lattice[k]);
  }
  const int along = NormalSign(A, B, C, a);
  assert(along != 0);
  int o = Orient3D(A, B, C, Z); // sign of n.(A - Z)
  for (int k = 0; o == 0 && k < 3; ++k)
  {
    o = -NormalSign(A, B, C, k); // -n.d, d = (eps, eps^2, eps^3)
  }
  return o * along;
}

int MeshArrangement::Side(const ArrangementPoint& p, int axis, LatticeIndex coordinate) const
{
  const std::int64_t fixed = p.FixedCoordinate(axis);
  if (fixed >= 0)
  {
    assert(fixed != static_cast<std::int64_t>(coordinate));
    return fixed < static_cast<std::int64_t>(coordinate) ? -1 : 1;
  }
  const double c = this->Grid.Coordinate(axis, coordinate);
  switch (p.PointKind)
  {
    case ArrangementPoint::Kind::MeshVertex:
      return this->VertexSide(this->Solid.Points()[p.A], axis, c);
    case ArrangementPoint::Kind::EdgeOnPlane:
      return this->EdgeSide(p, axis, c);
    default:
      return this->TriangleSide(p, axis, c);
  }
}

Vec3 MeshArrangement::Position(const ArrangementPoint& p) const
{
  if (p.PointKind == ArrangementPoint::Kind::MeshVertex)
  {
    return this->Solid.Points()[p.A];
  }
  if (p.PointKind == ArrangementPoint::Kind::EdgeOnPlane)
  {
    const int b = p.Axis;
    const Vec3& P = this->Solid.Points()[p.A];
    const Vec3& Q = this->Solid.Points()[p.B];
    const double e = this->Grid.Coordinate(b, p.Lattice[b]);
    Vec3 x = P + (Q - P) * ((e - P[b]) / (Q[b] - P[b]));
    x[b] = e;
    return x;
  }
  const int a = p.Axis;
  const std::uint32_t t = p.A;
  const Vec3& A = this->Solid.Vertex(t, 0);
  const Vec3 n = Cross(this->Solid.Vertex(t, 1) - A, this->Solid.Vertex(t, 2) - A);
  Vec3 y;
  double rest = Dot(n, A);
  for (int k = 0; k < 3; ++k)
  {
    if (k != a)
    {
      y[k] = this->Grid.Coordinate(k, p.Lattice[k]);
      rest -= n[k] * y[k];
    }
  }
  y[a] = rest / n[a];
  return y;
}

bool MeshArrangement::PlacedAsDecided(const ArrangementPoint& p, const Vec3& position) const
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (p.FixedCoordinate(axis) >= 0)
    {
      continue; // (on its lattice plane or line exactly)
    }
    const double x = position[axis];
    const LatticeIndex extent = static_cast<LatticeIndex>(this->Grid.Dims[axis]) << this->Grid.MaxDepth;
    const double guess = std::floor((x - this->Grid.Origin[axis]) / this->Grid.Spacing());
    if (!(guess >= 0.0 && guess < static_cast<double>(extent)))
    {
      return false; // outside the lattice
    }
    // The lattice planes i and i + 1 around x, as rounded, must have p
    // between them by the exact tests too (then every lattice plane does).
    const LatticeIndex i = static_cast<LatticeIndex>(guess);
    const double lo = this->Grid.Coordinate(axis, i), hi = this->Grid.Coordinate(axis, i + 1);
    if (!(lo < x && x < hi && this->Side(p, axis, i) > 0 && this->Side(p, axis, i + 1) < 0))
    {
      return false;
    }
  }
  return true;
}

std::vector<ClippedVertex> MeshArrangement::ClipTriangle(
  std::uint32_t t, const LatticeIndex lo[3], const LatticeIndex hi[3]) const
{
  const auto& tri = this->Solid.Triangles()[t];
  std::vector<ClippedVertex> polygon = { { ArrangementPoint::Vertex(tri[0]), 0 },
    { ArrangementPoint::Vertex(tri[1]), 1 }, { ArrangementPoint::Vertex(tri[2]), 2 } };
  std::vector<ClippedVertex> next;
  for (int f = 0; f < 6 && !polygon.empty(); ++f)
  {
    const int axis = f / 2;
    const bool high = f % 2 != 0;
    const LatticeIndex plane = high ? hi[axis] : lo[axis];
    auto inside = [&](const ArrangementPoint& p) { return this->Side(p, axis, plane) == (high ? -1 : 1); };
    // Where the polygon edge with `support` crosses this plane: on an edge of
    // the triangle, or on the lattice line where the face it lies on meets
    // this plane.
    auto crossing = [&](int support) {
      if (support < ClippedVertex::FaceSupport)
      {
        return ArrangementPoint::EdgeOnPlane(tri[static_cast<std::size_t>(support)], tri[(support + 1) % 3], axis, plane);
      }
      const int face = support - ClippedVertex::FaceSupport, faceAxis = face / 2;
      LatticeIndex line[3] = { 0, 0, 0 };
      line[faceAxis] = face % 2 ? hi[faceAxis] : lo[faceAxis];
      line[axis] = plane;
      return ArrangementPoint::TriangleOnLine(t, 3 - faceAxis - axis, line);
    };
    next.clear();
    const std::size_t m = polygon.size();
    for (std::size_t i = 0; i < m; ++i)
    {
      const ClippedVertex& p = polygon[i];
      const ClippedVertex& q = polygon[(i + 1) % m];
      const bool inP = inside(p.Point), inQ = inside(q.Point);
      if (inP)
      {
        next.push_back(p);
      }
      if (inP != inQ)
      {
        // Leaving: the edge on to the next entering crossing lies on this
        // face. Entering: the edge on to q keeps p's support.
        next.push_back({ crossing(p.Support), inP ? ClippedVertex::FaceSupport + f : p.Support });
      }
    }
    polygon.swap(next);
  }
  return polygon;
}

bool MeshArrangement::TraceOnRectangle(std::uint32_t t, int axis, LatticeIndex plane, const LatticeIndex lo[2],
  const LatticeIndex hi[2], int outward, int sigma, ArrangementPoint& from, ArrangementPoint& to) const
{
  const auto& tri = this->Solid.Triangles()[t];
  const double c = this->Grid.Coordinate(axis, plane);
  int side[3];
  for (int k = 0; k < 3; ++k)
  {
    side[k] = this->VertexSide(this->Solid.Points()[tri[k]], axis, c);
  }
  if (side[0] == side[1] && side[1] == side[2])
  {
    return false;
  }
  const int lone = side[0] != side[1] && side[0] != side[2] ? 0 : (side[1] != side[0] ? 1 : 2);
  const std::uint32_t before = tri[(lone + 2) % 3], at = tri[static_cast<std::size_t>(lone)], after = tri[(lone + 1) % 3];
  // For an outward triangle cut with its lone vertex on the side the face
  // normal points to, the trace runs from the edge entering that vertex to
  // the edge leaving it (the solid on its right seen from that side).
  const ArrangementPoint in = ArrangementPoint::EdgeOnPlane(before, at, axis, plane);
  const ArrangementPoint out = ArrangementPoint::EdgeOnPlane(at, after, axis, plane);
  const bool forward = side[lone] * outward * sigma > 0;
  from = forward ? in : out;
  to = forward ? out : in;
  for (int k = 0; k < 4; ++k)
  {
    const int u = (axis + 1 + k / 2) % 3, w = 3 - axis - u; // bound along u; the clipped point moves along w
    const bool high = k % 2 != 0;
    const LatticeIndex bound = high ? hi[k / 2] : lo[k / 2];
    const int keep = high ? -1 : 1;
    const bool inFrom = this->Side(from, u, bound) == keep, inTo = this->Side(to, u, bound) == keep;
    if (!inFrom && !inTo)
    {
      return false;
    }
    if (inFrom != inTo)
    {
      LatticeIndex line[3] = { 0, 0, 0 };
      line[axis] = plane;
      line[u] = bound;
      (inFrom ? to : from) = ArrangementPoint::TriangleOnLine(t, w, line);
    }
  }
  return true;
}

bool MeshArrangement::Before(
  const ArrangementPoint& from, const ArrangementPoint& a, int axisB, LatticeIndex coordinateB) const
{
  return this->Side(a, axisB, coordinateB) == this->Side(from, axisB, coordinateB);
}

} // namespace tpc
