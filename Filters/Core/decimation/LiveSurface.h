// The surface a certified decimation works on (CertifiedDecimation.h), and
// what a collapse would make of it.
//
// Triangles keep their ids for the whole decimation: a collapse rewrites the
// triangles that take To for From in place and marks the two that vanish
// dead, so bounds, labels and witnesses stay attached by id. Around lists
// the live triangles at each vertex (a vertex's star), Grid lists every live
// triangle under its box (TriangleGrid.h: never misses one). Everything here
// reads the surface as it is; only Apply changes it.
#pragma once

#include "ReleasableArray.h"
#include "TriangleGrid.h"
#include "TriangleMesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace tpc
{

inline bool Holds(const Triangle& t, std::uint32_t v)
{
  return t[0] == v || t[1] == v || t[2] == v;
}

Box3 GrownBy(Box3 box, double margin);
/// The smallest box holding both.
Box3 Union(Box3 a, const Box3& b);
/// The box of `triangles` (at least one).
Box3 BoxOf(const Vec3* points, const std::vector<Triangle>& triangles);
/// The edges of `triangles`, each once, as (lower, higher) vertex ids.
std::vector<std::pair<std::uint32_t, std::uint32_t>> EdgesOf(const std::vector<Triangle>& triangles);

/// Which items one search has visited: a stamp per item, bumped per search
/// (no clearing between searches). One per thread (CertifiedDecimation.h,
/// Parallel).
struct VisitMarks
{
  std::vector<std::uint32_t> Stamp;
  std::uint32_t Current = 0;

  void Start(std::size_t items)
  {
    if (this->Stamp.size() < items)
    {
      this->Stamp.resize(items, 0);
    }
    // (After 2^32 searches the stamp comes round to values items still
    // hold: in the search that reused 0 every item never visited (or added
    // since) would look visited, and an item stamped k would again in the
    // search k + 2^32. Cleared then, once.)
    if (++this->Current == 0)
    {
      std::fill(this->Stamp.begin(), this->Stamp.end(), 0u);
      this->Current = 1;
    }
  }
  /// True the first time `i` is visited in this search.
  bool First(std::uint32_t i)
  {
    if (this->Stamp[i] == this->Current)
    {
      return false;
    }
    this->Stamp[i] = this->Current;
    return true;
  }
  bool Visited(std::uint32_t i) const { return this->Stamp[i] == this->Current; }
};

/// What one collapse of From onto To would do: the star's triangles that
/// vanish (holding both), those that take To for From, and what they become.
struct Collapse
{
  std::uint32_t From = 0;
  std::uint32_t To = 0;
  std::vector<std::uint32_t> Vanishing;
  std::vector<std::uint32_t> Kept;
  std::vector<Triangle> Made; ///< Kept's triangles after the move, in Kept's order
  /// Against the mesh: S's triangles measured by (b), each with its new
  /// witness (or none), set when the collapse is applied
  /// (CertifiedDecimation.h, Witnesses).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> Witnesses;
};

class LiveSurface
{
public:
  /// `labels`: the solid each triangle lies on, or empty (all one); an edge
  /// between labels, or whose triangles' normals differ by more than
  /// `featureAngle` degrees, is a feature. The grid's buckets `bucketWidth`
  /// wide.
  LiveSurface(const TriangleMesh& mesh, const ReleasableArray<std::int32_t>& labels, double featureAngle,
    double bucketWidth);

  const Vec3* P;
  std::vector<Triangle> Triangles;
  std::vector<char> Alive;
  /// The live triangles around each vertex.
  std::vector<std::vector<std::uint32_t>> Around;
  TriangleGrid Grid;

  Vec3 Normal(const Triangle& t) const
  {
    return Normalized(Cross(this->P[t[1]] - this->P[t[0]], this->P[t[2]] - this->P[t[0]]));
  }
  std::array<Vec3, 3> CornersOf(const Triangle& t) const { return { this->P[t[0]], this->P[t[1]], this->P[t[2]] }; }
  /// The vertices sharing a live triangle with v, sorted.
  std::vector<std::uint32_t> Neighbours(std::uint32_t v) const;
  /// The live triangles holding both a and b (two in a closed manifold).
  std::vector<std::uint32_t> EdgeTriangles(std::uint32_t a, std::uint32_t b) const;
  bool IsFeature(std::uint32_t a, std::uint32_t b) const;
  bool Bent(const Vec3& n1, std::int32_t label1, const Vec3& n2, std::int32_t label2) const
  {
    return Dot(n1, n2) < this->CosFeatureAngle || label1 != label2;
  }
  std::int32_t LabelOf(std::uint32_t t) const
  {
    return this->Labels.size() == this->Triangles.size() ? this->Labels[t] : 0;
  }

  /// Calls visit(o) once for each live triangle whose box overlaps `box`.
  template <typename Visit>
  void ForEachLive(const Box3& box, VisitMarks& marks, Visit&& visit) const
  {
    marks.Start(this->Triangles.size());
    this->Grid.ForEachListed(box, [&](std::uint32_t o) {
      if (marks.First(o) && this->Alive[o] && TriangleBox(this->P, this->Triangles[o]).Overlaps(box))
      {
        visit(o);
      }
    });
  }
  /// Calls visit(o) once for each live triangle but the star of c.From
  /// whose box overlaps `box`.
  template <typename Visit>
  void ForEachOther(const Collapse& c, const Box3& box, VisitMarks& marks, Visit&& visit) const
  {
    this->ForEachLive(box, marks, [&](std::uint32_t o) {
      if (!Holds(this->Triangles[o], c.From))
      {
        visit(o);
      }
    });
  }

  /// Fills c's triangles from c.From and c.To; false unless the edge has
  /// its two triangles and From has others.
  bool Describe(Collapse& c) const;
  /// The star's triangles, vanishing then kept, as they are before `c`.
  std::vector<Triangle> StarOf(const Collapse& c) const;
  /// Once `c` is made, do exactly two triangles hold the edge x y (named
  /// after it), and are they bent (`bent`)?
  bool EdgeAfter(const Collapse& c, std::uint32_t x, std::uint32_t y, bool& bent) const;
  /// Is x y a feature edge once `c` is made (x, y named after it)?
  bool IsFeatureAfter(const Collapse& c, std::uint32_t x, std::uint32_t y) const
  {
    bool bent = false;
    return !this->EdgeAfter(c, x, y, bent) || bent;
  }
  /// CertifiedDecimation.h, Topology (Dey et al.).
  bool LinkConditionHolds(const Collapse& c) const;
  /// No made triangle degenerate or turned over against the one it replaces.
  bool KeepsShape(const Collapse& c) const;

  /// Makes `c`: its vanishing triangles dead, its kept ones made.
  void Apply(const Collapse& c);

private:
  const ReleasableArray<std::int32_t>& Labels;
  double CosFeatureAngle;
};

} // namespace tpc
