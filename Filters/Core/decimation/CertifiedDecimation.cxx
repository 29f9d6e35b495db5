#include "CertifiedDecimation.h"

#include "ConvexPolygons.h"
#include "ExactPredicates.h"
#include "PolygonHausdorff.h"
#include "ScratchPool.h"
#include "SelfIntersection.h"
#include "SharpCreases.h"
#include "TriangleGrid.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <queue>
#include <cstdio>

namespace tpc
{
namespace
{

bool Holds(const Triangle& t, std::uint32_t v)
{
  return t[0] == v || t[1] == v || t[2] == v;
}

Triangle Replaced(Triangle t, std::uint32_t v, std::uint32_t u)
{
  for (std::uint32_t& x : t)
  {
    x = x == v ? u : x;
  }
  return t;
}

/// The vertex of `t` that is neither a nor b.
std::uint32_t Opposite(const Triangle& t, std::uint32_t a, std::uint32_t b)
{
  for (const std::uint32_t x : t)
  {
    if (x != a && x != b)
    {
      return x;
    }
  }
  return t[0];
}

/// Moving From onto To; cheaper first (CertifiedDecimation.h: Order).
struct Candidate
{
  double Cost = 0.0;
  double Length = 0.0;
  std::uint32_t From = 0;
  std::uint32_t To = 0;
  std::uint32_t Stamp = 0;

  bool operator>(const Candidate& o) const
  {
    return this->Cost != o.Cost ? this->Cost > o.Cost : this->Length > o.Length;
  }
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
  /// witness (or none), set in Apply (header: Witnesses).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> Witnesses;
};

/// Why a collapse examined is refused, or that it is certified.
enum class Verdict
{
  Certified,
  Link,
  Feature,
  Shape,
  Error,
  Embedding
};

struct Examined
{
  Collapse What;
  Verdict Outcome = Verdict::Link;
  double Bound = 0.0; ///< the made triangles' bound, when certified
};

/// Which items one search has visited: a stamp per item, bumped per search
/// (no clearing between searches).
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
    ++this->Current;
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

/// One thread's marks while it examines collapses (header: Parallel).
struct ExamineScratch
{
  VisitMarks Triangles; ///< the surface's live triangles
  VisitMarks Star;      ///< the star's triangles
  VisitMarks Surface;   ///< S's triangles
  VisitMarks Sharp;     ///< S's sharp crease segments
};

/// Collapses examined together (header: Parallel): enough to keep two to
/// a few threads busy, few enough that the order stays nearly the heap's.
constexpr std::size_t CollapsesPerBatch = 16;

class Decimator
{
public:
  Decimator(TriangleMesh& mesh, std::vector<double>& bounds, ReleasableArray<std::int32_t>& labels,
    const DecimationParameters& parameters, const ExactMesh& surface);

  void Run(const ParallelFor& parallelFor);
  void Compact();

  DecimationResult Result;

private:
  Vec3 Normal(const Triangle& t) const
  {
    return Normalized(Cross(this->P[t[1]] - this->P[t[0]], this->P[t[2]] - this->P[t[0]]));
  }
  std::vector<std::uint32_t> Neighbours(std::uint32_t v) const;
  /// The live triangles holding both a and b (two in a closed manifold).
  std::vector<std::uint32_t> EdgeTriangles(std::uint32_t a, std::uint32_t b) const;
  bool IsFeature(std::uint32_t a, std::uint32_t b) const;
  SourceTriangle CornersOf(const Triangle& t) const { return { this->P[t[0]], this->P[t[1]], this->P[t[2]] }; }
  /// The star's triangles, vanishing then kept, as they are before `c`.
  std::vector<Triangle> StarOf(const Collapse& c) const;
  std::int32_t LabelOf(std::uint32_t t) const
  {
    return this->Labels.size() == this->Triangles.size() ? this->Labels[t] : 0;
  }
  bool Bent(const Vec3& n1, std::int32_t label1, const Vec3& n2, std::int32_t label2) const
  {
    return Dot(n1, n2) < this->CosFeatureAngle || label1 != label2;
  }
  void Queue(std::uint32_t v);
  /// Pops the next batch of collapses to examine together (header: Parallel).
  void FormBatch(std::vector<Candidate>& batch);
  /// Whether `c` reads nothing the batch's collapses write; if so, it joins.
  bool Claim(const Candidate& c);
  /// Every check of moving `from` onto `to`, on the surface as it is (reads only).
  Examined Examine(std::uint32_t from, std::uint32_t to, ExamineScratch& scratch) const;
  bool Describe(Collapse& c) const;
  bool MovesAlongFeatures(const Collapse& c) const;
  bool LinkConditionHolds(const Collapse& c) const;
  bool KeepsShape(const Collapse& c) const;
  bool MakesNoFeature(const Collapse& c) const;
  bool KeepsFeatures(const Collapse& c) const;
  bool KeepsCreasesFollowed(const Collapse& c, ExamineScratch& scratch) const;
  /// Once `c` is made, do exactly two triangles hold the edge x y (named
  /// after it), and are they bent (`bent`)?
  bool EdgeAfter(const Collapse& c, std::uint32_t x, std::uint32_t y, bool& bent) const;
  /// Is x y a feature edge once `c` is made (x, y named after it)?
  bool IsFeatureAfter(const Collapse& c, std::uint32_t x, std::uint32_t y) const
  {
    bool bent = false;
    return !this->EdgeAfter(c, x, y, bent) || bent;
  }
  double Certify(Collapse& c, ExamineScratch& scratch) const;
  double CertifyThroughBounds(const Collapse& c) const;
  double CertifyAgainstMesh(Collapse& c, ExamineScratch& scratch) const;
  /// Calls visit(o) once for each live triangle whose box overlaps `box`.
  template <typename Visit>
  void ForEachLive(const Box3& box, VisitMarks& marks, Visit&& visit) const;
  /// Calls visit(o) once for each live triangle but the star's whose box
  /// overlaps `box`.
  template <typename Visit>
  void ForEachOther(const Collapse& c, const Box3& box, VisitMarks& marks, Visit&& visit) const;
  /// S's triangles whose boxes overlap `box`, as polygons.
  void NearSurface(const Box3& box, PolygonSet& polygons, VisitMarks& marks) const;
  /// S's triangles overlapping `region` that no live triangle outside the
  /// star witnesses (header: Witnesses): whole where they lie in `region`,
  /// else clipped to it and fanned; `from` names each piece's triangle and
  /// whether it is whole.
  void UnwitnessedNear(const Collapse& c, const Box3& region, std::vector<SourceTriangle>& pieces,
    std::vector<std::pair<std::uint32_t, bool>>& from, ExamineScratch& scratch) const;
  bool MeetsAnother(const Collapse& c, ExamineScratch& scratch) const;
  bool SweepsOverAnother(const Collapse& c, ExamineScratch& scratch) const;
  void Count(Verdict outcome);
  void Apply(const Collapse& c, double bound);

  TriangleMesh& Mesh;
  std::vector<double>& Bounds;
  ReleasableArray<std::int32_t>& Labels;
  DecimationParameters Parameters;
  double CosFeatureAngle = 0.0;
  double Slack = 0.0;
  const Vec3* P = nullptr;
  std::vector<Triangle> Triangles;
  std::vector<char> Alive;
  /// The live triangles around each vertex.
  std::vector<std::vector<std::uint32_t>> Around;
  /// Bumped when a vertex's star changes: older candidates are stale.
  std::vector<std::uint32_t> Stamp;
  TriangleGrid Grid;
  /// The batch being formed: the boxes of what its collapses write (Claim).
  std::vector<Box3> WrittenBoxes;
  ExactMesh Surface;
  /// S's triangles, when collapses are certified against S.
  TriangleGrid SurfaceGrid;
  /// Per triangle of S: a live triangle within the tolerance of all of it,
  /// or None (header: Witnesses).
  std::vector<std::uint32_t> Witness;
  /// S's sharp creases (SharpCreases.h), when S is known.
  std::vector<EdgeSegment> Sharp;
  TriangleGrid SharpGrid;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> Heap;
};

Box3 PointsBox(const ReleasableArray<Vec3>& points)
{
  return points.empty() ? Box3{} : BoundsOf(points.data(), points.size());
}

/// Bucket width: a few tolerances, but no more than 2^20 buckets across the
/// surface's box on any axis (TriangleGrid keys hold 21 bits per axis).
double BucketWidth(const Box3& box, double tolerance)
{
  double widest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    widest = std::max(widest, box.Width(a));
  }
  return std::max({ 4.0 * tolerance, widest / 1048576.0, DBL_MIN });
}

Box3 GrownBy(Box3 box, double margin)
{
  for (int a = 0; a < 3; ++a)
  {
    box.lo[a] -= margin;
    box.hi[a] += margin;
  }
  return box;
}

/// The smallest box holding both.
Box3 Union(Box3 a, const Box3& b)
{
  for (int k = 0; k < 3; ++k)
  {
    a.lo[k] = std::min(a.lo[k], b.lo[k]);
    a.hi[k] = std::max(a.hi[k], b.hi[k]);
  }
  return a;
}

Box3 BoxOf(const Vec3* points, const std::vector<Triangle>& triangles)
{
  Box3 box = TriangleBox(points, triangles.front());
  for (const Triangle& t : triangles)
  {
    box = Union(box, TriangleBox(points, t));
  }
  return box;
}

Decimator::Decimator(TriangleMesh& mesh, std::vector<double>& bounds, ReleasableArray<std::int32_t>& labels,
  const DecimationParameters& parameters, const ExactMesh& surface)
  : Mesh(mesh)
  , Bounds(bounds)
  , Labels(labels)
  , Parameters(parameters)
  , CosFeatureAngle(std::cos(parameters.FeatureAngle * M_PI / 180.0))
  , P(mesh.Points.data())
  , Triangles(mesh.Triangles.begin(), mesh.Triangles.end())
  , Alive(mesh.Triangles.size(), 1)
  , Around(mesh.Points.size())
  , Stamp(mesh.Points.size(), 0)
  , Grid(PointsBox(mesh.Points).lo, BucketWidth(PointsBox(mesh.Points), parameters.Tolerance))
  , Surface(surface)
  , SurfaceGrid(PointsBox(mesh.Points).lo, BucketWidth(PointsBox(mesh.Points), parameters.Tolerance))
  , SharpGrid(PointsBox(mesh.Points).lo, BucketWidth(PointsBox(mesh.Points), parameters.Tolerance))
{
  // Distances are computed in floating point (PolygonHausdorff.h): the same
  // slack as the cells' certificates (MeshCellError.cxx, RoundingSlack).
  const Box3 box = PointsBox(mesh.Points);
  this->Slack = 4096.0 * DBL_EPSILON * box.Magnitude() + 1e-12 * box.Diagonal();
  for (std::uint32_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (const std::uint32_t v : this->Triangles[t])
    {
      this->Around[v].push_back(t);
    }
    this->Grid.Insert(t, TriangleBox(this->P, this->Triangles[t]));
  }
  this->Result.TrianglesBefore = this->Triangles.size();
  for (const double e : bounds)
  {
    this->Result.Bound = std::max(this->Result.Bound, e);
  }
  if (surface.Mesh)
  {
    const std::vector<Triangle>& triangles = surface.Mesh->Triangles();
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
    {
      this->SurfaceGrid.Insert(t, TriangleBox(surface.Mesh->Points().data(), triangles[t]));
    }
    this->Witness.assign(triangles.size(), SingleTargetWitness::None);
    this->Sharp = SharpEdges(*surface.Mesh, SharpCreaseAngle);
    for (std::uint32_t k = 0; k < this->Sharp.size(); ++k)
    {
      const Vec3 ends[2] = { this->Sharp[k].A, this->Sharp[k].B };
      this->SharpGrid.Insert(k, BoundsOf(ends, 2));
    }
  }
}

std::vector<std::uint32_t> Decimator::Neighbours(std::uint32_t v) const
{
  std::vector<std::uint32_t> n;
  for (const std::uint32_t t : this->Around[v])
  {
    for (const std::uint32_t x : this->Triangles[t])
    {
      if (x != v)
      {
        n.push_back(x);
      }
    }
  }
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

std::vector<std::uint32_t> Decimator::EdgeTriangles(std::uint32_t a, std::uint32_t b) const
{
  std::vector<std::uint32_t> both;
  for (const std::uint32_t t : this->Around[a])
  {
    if (Holds(this->Triangles[t], b))
    {
      both.push_back(t);
    }
  }
  return both;
}

bool Decimator::IsFeature(std::uint32_t a, std::uint32_t b) const
{
  const std::vector<std::uint32_t> both = this->EdgeTriangles(a, b);
  if (both.size() != 2)
  {
    return true; // (not an edge of a closed manifold: never moved)
  }
  return this->Bent(this->Normal(this->Triangles[both[0]]), this->LabelOf(both[0]),
    this->Normal(this->Triangles[both[1]]), this->LabelOf(both[1]));
}

void Decimator::Queue(std::uint32_t v)
{
  for (const std::uint32_t u : this->Neighbours(v))
  {
    Candidate c;
    c.From = v;
    c.To = u;
    c.Stamp = this->Stamp[v];
    const Vec3 move = this->P[u] - this->P[v];
    c.Length = Norm(move);
    for (const std::uint32_t t : this->Around[v])
    {
      if (!Holds(this->Triangles[t], u))
      {
        c.Cost = std::max(c.Cost, std::fabs(Dot(this->Normal(this->Triangles[t]), move)));
      }
    }
    this->Heap.push(c);
  }
}

std::vector<Triangle> Decimator::StarOf(const Collapse& c) const
{
  std::vector<Triangle> star;
  for (const std::vector<std::uint32_t>* part : { &c.Vanishing, &c.Kept })
  {
    for (const std::uint32_t t : *part)
    {
      star.push_back(this->Triangles[t]);
    }
  }
  return star;
}

/// The edges of `triangles`, each once, as (lower, higher) vertex ids.
std::vector<std::pair<std::uint32_t, std::uint32_t>> EdgesOf(const std::vector<Triangle>& triangles)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

bool Decimator::Describe(Collapse& c) const
{
  for (const std::uint32_t t : this->Around[c.From])
  {
    if (Holds(this->Triangles[t], c.To))
    {
      c.Vanishing.push_back(t);
    }
    else
    {
      c.Kept.push_back(t);
      c.Made.push_back(Replaced(this->Triangles[t], c.From, c.To));
    }
  }
  return c.Vanishing.size() == 2 && !c.Kept.empty();
}

bool Decimator::MovesAlongFeatures(const Collapse& c) const
{
  std::size_t features = 0;
  bool towardsTo = false;
  for (const std::uint32_t w : this->Neighbours(c.From))
  {
    if (this->IsFeature(c.From, w))
    {
      ++features;
      towardsTo |= w == c.To;
    }
  }
  return features == 0 || (features == 2 && towardsTo);
}

bool Decimator::LinkConditionHolds(const Collapse& c) const
{
  const std::uint32_t w1 = Opposite(this->Triangles[c.Vanishing[0]], c.From, c.To);
  const std::uint32_t w2 = Opposite(this->Triangles[c.Vanishing[1]], c.From, c.To);
  if (w1 == w2)
  {
    return false;
  }
  const std::vector<std::uint32_t> a = this->Neighbours(c.From), b = this->Neighbours(c.To);
  std::vector<std::uint32_t> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  if (common.size() != 2)
  {
    return false;
  }
  // (The one edge both links could share: w1 w2, when both triangles
  // From w1 w2 and To w1 w2 exist - a tetrahedron.)
  auto hasTriangle = [this, w1, w2](std::uint32_t x) {
    for (const std::uint32_t t : this->Around[x])
    {
      if (Holds(this->Triangles[t], w1) && Holds(this->Triangles[t], w2))
      {
        return true;
      }
    }
    return false;
  };
  return !(hasTriangle(c.From) && hasTriangle(c.To));
}

bool Decimator::KeepsShape(const Collapse& c) const
{
  for (std::size_t i = 0; i < c.Made.size(); ++i)
  {
    const Triangle& t = c.Made[i];
    if (TriangleIsDegenerate(this->P[t[0]], this->P[t[1]], this->P[t[2]]) ||
      !(Dot(this->Normal(t), this->Normal(this->Triangles[c.Kept[i]])) > 0.0))
    {
      return false;
    }
  }
  return true;
}

bool Decimator::KeepsFeatures(const Collapse& c) const
{
  // Every feature edge of the star but the one moved along keeps being one
  // (as its image: From's edges become To's; the vanishing triangles' edges
  // To w too, whose other triangle changes).
  for (const std::vector<std::uint32_t>* part : { &c.Kept, &c.Vanishing })
  {
    for (const std::uint32_t t : *part)
    {
      const Triangle& old = this->Triangles[t];
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t u = old[k], v = old[(k + 1) % 3];
        const std::uint32_t x = u == c.From ? c.To : u, y = v == c.From ? c.To : v;
        if (x != y && this->IsFeature(u, v) && !this->IsFeatureAfter(c, x, y))
        {
          return false;
        }
      }
    }
  }
  return true;
}

bool Decimator::EdgeAfter(const Collapse& c, std::uint32_t x, std::uint32_t y, bool& bent) const
{
  std::vector<Vec3> normals;
  std::vector<std::int32_t> labels;
  for (std::size_t j = 0; j < c.Made.size(); ++j)
  {
    if (Holds(c.Made[j], x) && Holds(c.Made[j], y))
    {
      normals.push_back(this->Normal(c.Made[j]));
      labels.push_back(this->LabelOf(c.Kept[j]));
    }
  }
  for (const std::uint32_t o : this->Around[x])
  {
    if (!Holds(this->Triangles[o], c.From) && Holds(this->Triangles[o], y))
    {
      normals.push_back(this->Normal(this->Triangles[o]));
      labels.push_back(this->LabelOf(o));
    }
  }
  bent = normals.size() == 2 && this->Bent(normals[0], labels[0], normals[1], labels[1]);
  return normals.size() == 2;
}

bool Decimator::KeepsCreasesFollowed(const Collapse& c, ExamineScratch& scratch) const
{
  if (this->Sharp.empty())
  {
    return true;
  }
  // Removed: feature edges of the star that are not feature edges after
  // (gone, or no longer bent). Only edges with a triangle in the star change
  // (SharpCreases.h); most collapses remove none.
  // (An edge of From's is gone: removed if it was a feature.)
  std::vector<EdgeSegment> removed;
  for (const auto& [x, y] : EdgesOf(this->StarOf(c)))
  {
    const bool now = x != c.From && y != c.From && this->IsFeatureAfter(c, x, y);
    if (!now && this->IsFeature(x, y))
    {
      removed.push_back({ this->P[x], this->P[y] });
    }
  }
  if (removed.empty())
  {
    return true;
  }
  // The sharp creases within reach of a removed edge, and the feature edges
  // after within reach of those (from the triangles there).
  const double reach = this->Parameters.Tolerance - this->Slack;
  std::vector<Vec3> ends;
  for (const EdgeSegment& e : removed)
  {
    ends.insert(ends.end(), { e.A, e.B });
  }
  const Box3 region = GrownBy(BoundsOf(ends.data(), ends.size()), this->Parameters.Tolerance);
  std::vector<EdgeSegment> pieces;
  scratch.Sharp.Start(this->Sharp.size());
  this->SharpGrid.ForEachListed(region, [&](std::uint32_t k) {
    if (scratch.Sharp.First(k))
    {
      EdgeSegment piece = this->Sharp[k];
      if (ClipSegment(piece.A, piece.B, region))
      {
        pieces.push_back(piece);
      }
    }
  });
  if (pieces.empty())
  {
    return true;
  }
  std::vector<Triangle> near = c.Made;
  this->ForEachOther(c, GrownBy(region, this->Parameters.Tolerance), scratch.Triangles,
    [&](std::uint32_t o) { near.push_back(this->Triangles[o]); });
  std::vector<EdgeSegment> after;
  for (const auto& [x, y] : EdgesOf(near))
  {
    if (this->IsFeatureAfter(c, x, y))
    {
      after.push_back({ this->P[x], this->P[y] });
    }
  }
  for (const EdgeSegment& piece : pieces)
  {
    if (!StaysFollowed(piece.A, piece.B, removed, after, reach))
    {
      return false;
    }
  }
  return true;
}

bool Decimator::MakesNoFeature(const Collapse& c) const
{
  for (const Triangle& t : c.Made)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t x = t[k], y = t[(k + 1) % 3];
      bool bent = false;
      if (!this->EdgeAfter(c, x, y, bent))
      {
        return false; // (never in a closed manifold after a collapse the link condition allows)
      }
      if (!bent)
      {
        continue;
      }
      // A feature now: it must be the image of one before (From's edges
      // become To's).
      const std::uint32_t z = x == c.To ? y : (y == c.To ? x : c.From);
      const bool before = z == c.From ? this->IsFeature(x, y)
                                      : this->IsFeature(c.From, z) ||
          (this->EdgeTriangles(c.To, z).size() == 2 && this->IsFeature(c.To, z));
      if (!before)
      {
        return false;
      }
    }
  }
  return true;
}

double Decimator::Certify(Collapse& c, ExamineScratch& scratch) const
{
  return this->Surface.Mesh ? this->CertifyAgainstMesh(c, scratch) : this->CertifyThroughBounds(c);
}

template <typename Visit>
void Decimator::ForEachLive(const Box3& box, VisitMarks& marks, Visit&& visit) const
{
  marks.Start(this->Triangles.size());
  this->Grid.ForEachListed(box, [&](std::uint32_t o) {
    if (marks.First(o) && this->Alive[o] && TriangleBox(this->P, this->Triangles[o]).Overlaps(box))
    {
      visit(o);
    }
  });
}

template <typename Visit>
void Decimator::ForEachOther(const Collapse& c, const Box3& box, VisitMarks& marks, Visit&& visit) const
{
  this->ForEachLive(box, marks, [&](std::uint32_t o) {
    if (!Holds(this->Triangles[o], c.From))
    {
      visit(o);
    }
  });
}

void Decimator::NearSurface(const Box3& box, PolygonSet& polygons, VisitMarks& marks) const
{
  const Vec3* points = this->Surface.Mesh->Points().data();
  const std::vector<Triangle>& triangles = this->Surface.Mesh->Triangles();
  marks.Start(triangles.size());
  this->SurfaceGrid.ForEachListed(box, [&](std::uint32_t s) {
    if (!marks.First(s) || !TriangleBox(points, triangles[s]).Overlaps(box))
    {
      return;
    }
    const Triangle& t = triangles[s];
    polygons.Add({ points[t[0]], points[t[1]], points[t[2]] });
  });
}

void Decimator::UnwitnessedNear(const Collapse& c, const Box3& region, std::vector<SourceTriangle>& pieces,
  std::vector<std::pair<std::uint32_t, bool>>& from, ExamineScratch& scratch) const
{
  scratch.Star.Start(this->Triangles.size());
  for (const std::vector<std::uint32_t>* part : { &c.Vanishing, &c.Kept })
  {
    for (const std::uint32_t t : *part)
    {
      scratch.Star.First(t);
    }
  }
  const Vec3* points = this->Surface.Mesh->Points().data();
  const std::vector<Triangle>& triangles = this->Surface.Mesh->Triangles();
  scratch.Surface.Start(triangles.size());
  this->SurfaceGrid.ForEachListed(region, [&](std::uint32_t s) {
    const Triangle& t = triangles[s];
    const Box3 box = TriangleBox(points, t);
    if (!scratch.Surface.First(s) || !box.Overlaps(region))
    {
      return;
    }
    const std::uint32_t w = this->Witness[s];
    if (w != SingleTargetWitness::None && this->Alive[w] && !scratch.Star.Visited(w))
    {
      return; // (its witness stays as it is)
    }
    if (region.Contains(box.lo) && region.Contains(box.hi))
    {
      pieces.push_back({ points[t[0]], points[t[1]], points[t[2]] });
      from.emplace_back(s, true);
      return;
    }
    ClippedCorners clipped;
    for (const std::uint32_t v : t)
    {
      clipped.push_back(points[v]);
    }
    ClipToBox(clipped, region);
    for (std::size_t i = 1; i + 1 < clipped.size(); ++i)
    {
      pieces.push_back({ clipped[0], clipped[i], clipped[i + 1] });
      from.emplace_back(s, false);
    }
    if (clipped.size() == 1 || clipped.size() == 2)
    {
      pieces.push_back({ clipped.front(), clipped.back(), clipped.back() });
      from.emplace_back(s, false);
    }
  });
}

double Decimator::CertifyAgainstMesh(Collapse& c, ExamineScratch& scratch) const
{
  const double tolerance = this->Parameters.Tolerance;
  const double giveUp = tolerance - this->Slack;
  const std::size_t budget = this->Parameters.CertificateBudget;
  // (a) The made triangles, to S near them.
  std::vector<SourceTriangle> made;
  PolygonSet madeSet;
  for (const Triangle& t : c.Made)
  {
    made.push_back(this->CornersOf(t));
    madeSet.Add({ made.back()[0], made.back()[1], made.back()[2] });
  }
  PolygonSet nearMade;
  this->NearSurface(GrownBy(BoxOf(this->P, c.Made), tolerance), nearMade, scratch.Surface);
  const HausdorffEstimate toSurface = OneSidedHausdorff(made, nearMade, giveUp, giveUp, budget);
  if (!(toSurface.Upper <= giveUp))
  {
    return HUGE_VAL;
  }
  // (b) S where the star was nearest (but where a triangle outside the star
  // witnesses it), to the surface after.
  const Box3 region = GrownBy(BoxOf(this->P, this->StarOf(c)), tolerance);
  std::vector<SourceTriangle> surfacePieces;
  std::vector<std::pair<std::uint32_t, bool>> from;
  this->UnwitnessedNear(c, region, surfacePieces, from, scratch);
  PolygonSet after = madeSet;
  std::vector<std::uint32_t> afterIds = c.Kept; // (the made triangles take the kept ones' ids)
  this->ForEachOther(c, GrownBy(region, tolerance), scratch.Triangles, [&](std::uint32_t o) {
    const SourceTriangle s = this->CornersOf(this->Triangles[o]);
    after.Add({ s[0], s[1], s[2] });
    afterIds.push_back(o);
  });
  std::vector<SingleTargetWitness> settled;
  const HausdorffEstimate covered = OneSidedHausdorff(surfacePieces, after, giveUp, giveUp, budget, {}, &settled);
  if (!(covered.Upper <= giveUp))
  {
    return HUGE_VAL;
  }
  // New witnesses: a whole triangle of S settled by one triangle after.
  double witnessed = 0.0;
  c.Witnesses.clear();
  for (std::size_t k = 0; k < from.size(); ++k)
  {
    const bool whole = from[k].second && settled[k].Target != SingleTargetWitness::None;
    c.Witnesses.emplace_back(from[k].first, whole ? afterIds[settled[k].Target] : SingleTargetWitness::None);
    witnessed = whole ? std::max(witnessed, settled[k].Bound) : witnessed;
  }
  return std::max({ toSurface.Upper, covered.Upper, witnessed }) + this->Slack;
}

double Decimator::CertifyThroughBounds(const Collapse& c) const
{
  std::vector<SourceTriangle> before, after;
  std::vector<double> offsets;
  PolygonSet beforeSet, afterSet;
  double largest = 0.0;
  for (const std::vector<std::uint32_t>* part : { &c.Vanishing, &c.Kept })
  {
    for (const std::uint32_t t : *part)
    {
      const SourceTriangle s = this->CornersOf(this->Triangles[t]);
      before.push_back(s);
      beforeSet.Add({ s[0], s[1], s[2] });
      offsets.push_back(this->Bounds[t]);
      largest = std::max(largest, this->Bounds[t]);
    }
  }
  for (const Triangle& t : c.Made)
  {
    const SourceTriangle s = this->CornersOf(t);
    after.push_back(s);
    afterSet.Add({ s[0], s[1], s[2] });
  }
  const double giveUp = this->Parameters.Tolerance - this->Slack;
  if (!(largest < giveUp))
  {
    return HUGE_VAL;
  }
  // Refined until a quarter of the room left (a looser bound would use up
  // the tolerance for the collapses after this one).
  const double enough = largest + 0.25 * (giveUp - largest);
  const std::size_t budget = this->Parameters.BoundsCertificateBudget;
  const HausdorffEstimate covered = OneSidedHausdorff(before, afterSet, enough, giveUp, budget, { &offsets, nullptr });
  if (!(covered.Upper <= giveUp))
  {
    return HUGE_VAL;
  }
  const HausdorffEstimate near = OneSidedHausdorff(after, beforeSet, enough, giveUp, budget, { nullptr, &offsets });
  if (!(near.Upper <= giveUp))
  {
    return HUGE_VAL;
  }
  return std::max(covered.Upper, near.Upper) + this->Slack;
}

bool Decimator::MeetsAnother(const Collapse& c, ExamineScratch& scratch) const
{
  for (std::size_t i = 0; i < c.Made.size(); ++i)
  {
    for (std::size_t j = i + 1; j < c.Made.size(); ++j)
    {
      if (TrianglesMeetImproperly(this->P, c.Made[i], c.Made[j]))
      {
        return true;
      }
    }
  }
  bool meets = false;
  for (const Triangle& t : c.Made)
  {
    // (The star's triangles are replaced by the made ones.)
    this->ForEachOther(c, TriangleBox(this->P, t), scratch.Triangles,
      [&](std::uint32_t o) { meets = meets || TrianglesMeetImproperly(this->P, t, this->Triangles[o]); });
    if (meets)
    {
      return true;
    }
  }
  return false;
}

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

/// Header, Embedding: does the pocket between the star and the made
/// triangles hold a vertex of another live triangle?
bool Decimator::SweepsOverAnother(const Collapse& c, ExamineScratch& scratch) const
{
  // The tetrahedra (From, To, a, b) over the made triangles' far edges ab.
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
    const int sign = Orient3D(this->P[c.From], this->P[c.To], this->P[a], this->P[b]);
    if (sign != 0)
    {
      swept.push_back({ { this->P[c.From], this->P[c.To], this->P[a], this->P[b] }, a, b, sign });
    }
  }
  if (swept.empty())
  {
    return false;
  }
  const Box3 box = BoxOf(this->P, this->StarOf(c)); // (N's vertices are O's)
  bool sweeps = false;
  this->ForEachOther(c, box, scratch.Triangles, [&](std::uint32_t o) {
    for (const std::uint32_t v : this->Triangles[o])
    {
      if (sweeps || v == c.To || !box.Contains(this->P[v]))
      {
        continue;
      }
      for (const Swept& s : swept)
      {
        // (A link vertex is a corner of its own tetrahedra.)
        if (v != s.A && v != s.B && InClosedTetrahedron(this->P[v], s.Corners, s.Sign))
        {
          sweeps = true;
          break;
        }
      }
    }
  });
  return sweeps;
}

void Decimator::Apply(const Collapse& c, double bound)
{
  for (const std::uint32_t t : c.Vanishing)
  {
    this->Alive[t] = 0;
    for (const std::uint32_t x : this->Triangles[t])
    {
      if (x != c.From)
      {
        std::vector<std::uint32_t>& around = this->Around[x];
        around.erase(std::find(around.begin(), around.end(), t));
      }
    }
  }
  for (std::size_t i = 0; i < c.Kept.size(); ++i)
  {
    const std::uint32_t t = c.Kept[i];
    this->Triangles[t] = c.Made[i];
    this->Bounds[t] = bound;
    this->Around[c.To].push_back(t);
    this->Grid.Insert(t, TriangleBox(this->P, c.Made[i]));
  }
  this->Around[c.From].clear();
  for (const auto& [s, w] : c.Witnesses)
  {
    this->Witness[s] = w;
  }
  ++this->Result.Collapses;
  // Every vertex whose star changed is queued again.
  std::vector<std::uint32_t> changed = this->Neighbours(c.To);
  changed.push_back(c.To);
  for (const std::uint32_t w : changed)
  {
    ++this->Stamp[w];
    this->Queue(w);
  }
}

Examined Decimator::Examine(std::uint32_t from, std::uint32_t to, ExamineScratch& scratch) const
{
  Examined e;
  Collapse& c = e.What;
  c.From = from;
  c.To = to;
  if (!this->Describe(c) || !this->LinkConditionHolds(c))
  {
    e.Outcome = Verdict::Link;
    return e;
  }
  // (Features: the input's sharp creases where S is known, else the
  // surface's own dihedral angles and labels - header, Features.)
  const bool byDihedral = !this->Surface.Mesh;
  if (byDihedral && !this->MovesAlongFeatures(c))
  {
    e.Outcome = Verdict::Feature;
    return e;
  }
  if (!this->KeepsShape(c))
  {
    e.Outcome = Verdict::Shape;
    return e;
  }
  if (byDihedral ? !this->MakesNoFeature(c) || !this->KeepsFeatures(c) : !this->KeepsCreasesFollowed(c, scratch))
  {
    e.Outcome = Verdict::Feature;
    return e;
  }
  e.Bound = this->Certify(c, scratch);
  if (!(e.Bound <= this->Parameters.Tolerance))
  {
    e.Outcome = Verdict::Error;
    return e;
  }
  e.Outcome = this->MeetsAnother(c, scratch) || this->SweepsOverAnother(c, scratch) ? Verdict::Embedding
                                                                                    : Verdict::Certified;
  return e;
}

void Decimator::Count(Verdict outcome)
{
  switch (outcome)
  {
    case Verdict::Certified:
      break; // (counted by Apply)
    case Verdict::Link:
      ++this->Result.RefusedByLink;
      break;
    case Verdict::Feature:
      ++this->Result.RefusedByFeature;
      break;
    case Verdict::Shape:
      ++this->Result.RefusedByShape;
      break;
    case Verdict::Error:
      ++this->Result.RefusedByError;
      break;
    case Verdict::Embedding:
      ++this->Result.RefusedByEmbedding;
      break;
  }
}

bool Decimator::Claim(const Candidate& c)
{
  // Read: what the live triangles overlapping the star's box grown by twice
  // the tolerance hold, and the lists around their vertices. Written: the
  // triangles around the star's vertices (header: Parallel).
  const std::vector<std::uint32_t>& star = this->Around[c.From];
  Box3 read = TriangleBox(this->P, this->Triangles[star.front()]);
  for (const std::uint32_t t : star)
  {
    read = Union(read, TriangleBox(this->P, this->Triangles[t]));
  }
  Box3 written = read;
  read = GrownBy(read, 2.0 * this->Parameters.Tolerance);
  for (const Box3& other : this->WrittenBoxes)
  {
    if (read.Overlaps(other))
    {
      return false;
    }
  }
  for (const std::uint32_t t : star)
  {
    for (const std::uint32_t v : this->Triangles[t])
    {
      for (const std::uint32_t o : this->Around[v])
      {
        written = Union(written, TriangleBox(this->P, this->Triangles[o]));
      }
    }
  }
  this->WrittenBoxes.push_back(written);
  return true;
}

void Decimator::FormBatch(std::vector<Candidate>& batch)
{
  batch.clear();
  this->WrittenBoxes.clear();
  std::vector<Candidate> deferred;
  while (!this->Heap.empty() && batch.size() < CollapsesPerBatch && deferred.size() < 3 * CollapsesPerBatch)
  {
    const Candidate c = this->Heap.top();
    this->Heap.pop();
    if (c.Stamp != this->Stamp[c.From] || this->Around[c.From].empty() || this->Around[c.To].empty())
    {
      continue; // (stale)
    }
    (this->Claim(c) ? batch : deferred).push_back(c);
  }
  for (const Candidate& c : deferred)
  {
    this->Heap.push(c);
  }
}

void Decimator::Run(const ParallelFor& parallelFor)
{
  // (Against the mesh, a collapse looks for the points of S it may leave
  // within the tolerance of its star: every point of S must be within the
  // tolerance of the surface before - header, Against the mesh.)
  if (!(this->Result.Bound <= this->Parameters.Tolerance))
  {
    return;
  }
  for (std::uint32_t v = 0; v < this->Around.size(); ++v)
  {
    this->Queue(v);
  }
  ScratchPool<ExamineScratch> scratch;
  std::vector<Candidate> batch;
  std::vector<Examined> examined;
  std::size_t tried = 0, reported = 0;
  while (!this->Heap.empty())
  {
    if (this->Parameters.Progress && tried >= reported + 1024)
    {
      reported = tried;
      if (this->Parameters.Progress(static_cast<double>(tried) / static_cast<double>(tried + this->Heap.size())))
      {
        this->Result.Aborted = true;
        return;
      }
    }
    this->FormBatch(batch);
    examined.assign(batch.size(), Examined{});
    parallelFor(batch.size(), [&](std::size_t begin, std::size_t end) {
      ScratchPool<ExamineScratch>::Lease marks(scratch);
      for (std::size_t i = begin; i < end; ++i)
      {
        examined[i] = this->Examine(batch[i].From, batch[i].To, *marks);
      }
    });
    // (In the batch's order: the same surface as examining and applying
    // them one after another, whatever the threads - header, Parallel.)
    for (std::size_t i = 0; i < examined.size(); ++i)
    {
      const Examined& e = examined[i];
      if (this->Parameters.CheckBatches)
      {
        ScratchPool<ExamineScratch>::Lease marks(scratch);
        const bool same = this->Examine(batch[i].From, batch[i].To, *marks).Outcome == e.Outcome;
        this->Result.BatchDisagreements += same ? 0 : 1;
      }
      this->Count(e.Outcome);
      if (e.Outcome == Verdict::Certified)
      {
        this->Apply(e.What, e.Bound);
        this->Result.Bound = std::max(this->Result.Bound, e.Bound);
      }
    }
    tried += batch.size();
  }
}

void Decimator::Compact()
{
  const std::uint32_t none = ~std::uint32_t{ 0 };
  std::vector<std::uint32_t> renumbered(this->Mesh.Points.size(), none);
  ReleasableArray<Vec3> points, normals;
  const bool hasNormals = this->Mesh.Normals.size() == this->Mesh.Points.size();
  ReleasableArray<Triangle> triangles;
  std::vector<std::uint32_t> cells;
  std::vector<double> bounds;
  ReleasableArray<std::int32_t> labels;
  const bool hasLabels = this->Labels.size() == this->Triangles.size();
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    if (!this->Alive[t])
    {
      continue;
    }
    Triangle kept = this->Triangles[t];
    for (std::uint32_t& v : kept)
    {
      if (renumbered[v] == none)
      {
        renumbered[v] = static_cast<std::uint32_t>(points.size());
        points.push_back(this->Mesh.Points[v]);
        if (hasNormals)
        {
          normals.push_back(this->Mesh.Normals[v]);
        }
      }
      v = renumbered[v];
    }
    triangles.push_back(kept);
    cells.push_back(this->Mesh.TriangleCell[t]);
    bounds.push_back(this->Bounds[t]);
    if (hasLabels)
    {
      labels.push_back(this->Labels[t]);
    }
  }
  this->Result.TrianglesAfter = triangles.size();
  this->Mesh.Points = std::move(points);
  this->Mesh.Normals = std::move(normals);
  this->Mesh.Triangles = std::move(triangles);
  this->Mesh.TriangleCell = std::move(cells);
  this->Bounds = std::move(bounds);
  if (hasLabels)
  {
    this->Labels = std::move(labels);
  }
  this->P = this->Mesh.Points.data();
}

} // namespace

DecimationResult DecimateCertified(TriangleMesh& mesh, std::vector<double>& bounds,
  ReleasableArray<std::int32_t>& labels, const DecimationParameters& parameters, const ExactMesh& surface,
  const ParallelFor& parallelFor)
{
  Decimator decimator(mesh, bounds, labels, parameters, surface);
  decimator.Run(parallelFor);
  decimator.Compact();
  return decimator.Result;
}

} // namespace tpc
