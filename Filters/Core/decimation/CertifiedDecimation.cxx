#include "CertifiedDecimation.h"

#include "CollapseEmbedding.h"
#include "ErrorCertificates.h"
#include "FeatureRules.h"
#include "LiveSurface.h"
#include "MeshCellError.h"
#include "ScratchPool.h"
#include "TopologyReport.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <queue>

namespace tpc
{
namespace
{

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

/// One thread's marks while it examines collapses (header: Parallel).
struct ExamineScratch
{
  CertificateMarks Certificate;
  VisitMarks Sharp; ///< S's sharp crease segments
};

/// Collapses examined together (header: Parallel): enough to keep two to
/// a few threads busy, few enough that the order stays nearly the heap's.
constexpr std::size_t CollapsesPerBatch = 16;

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

/// The decimation's state: the surface, each triangle's bound, the
/// candidates, and (against the mesh) S with its witnesses.
class Decimator
{
public:
  Decimator(TriangleMesh& mesh, std::vector<double>& bounds, ReleasableArray<std::int32_t>& labels,
    const DecimationParameters& parameters, const ExactMesh& surface);

  void Run(const ParallelFor& parallelFor);
  void Compact();

  DecimationResult Result;

private:
  void Queue(std::uint32_t v);
  /// Pops the next batch of collapses to examine together (header: Parallel).
  void FormBatch(std::vector<Candidate>& batch);
  /// Whether `c` reads nothing the batch's collapses write; if so, it joins.
  bool Claim(const Candidate& c);
  /// Every check of moving `from` onto `to`, on the surface as it is (reads only).
  Examined Examine(std::uint32_t from, std::uint32_t to, ExamineScratch& scratch) const;
  void Count(Verdict outcome);
  void Apply(const Collapse& c, double bound);

  TriangleMesh& Mesh;
  std::vector<double>& Bounds;
  ReleasableArray<std::int32_t>& Labels;
  DecimationParameters Parameters;
  Box3 Extent; ///< the surface's points' box: the grids' origin and width, the slack's scale
  double Slack;
  LiveSurface Live;
  /// Bumped when a vertex's star changes: older candidates are stale.
  std::vector<std::uint32_t> Stamp;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> Heap;
  /// The batch being formed: the boxes of what its collapses write (Claim).
  std::vector<Box3> WrittenBoxes;
  ErrorCertificates Error;
  SharpCreaseRule Creases;
};

Decimator::Decimator(TriangleMesh& mesh, std::vector<double>& bounds, ReleasableArray<std::int32_t>& labels,
  const DecimationParameters& parameters, const ExactMesh& surface)
  : Mesh(mesh)
  , Bounds(bounds)
  , Labels(labels)
  , Parameters(parameters)
  , Extent(PointsBox(mesh.Points))
  , Slack(RoundingSlackFor(this->Extent.Magnitude(), this->Extent.Diagonal()))
  , Live(mesh, labels, parameters.FeatureAngle, BucketWidth(this->Extent, parameters.Tolerance))
  , Stamp(mesh.Points.size(), 0)
  , Error(this->Live, bounds, this->Parameters, surface, this->Extent, BucketWidth(this->Extent, parameters.Tolerance))
  , Creases(surface.Mesh
        ? SharpCreaseRule(*surface.Mesh, this->Extent.lo, BucketWidth(this->Extent, parameters.Tolerance))
        : SharpCreaseRule(this->Extent.lo, 1.0))
{
  this->Result.TrianglesBefore = this->Live.Triangles.size();
  for (const double e : bounds)
  {
    this->Result.Bound = std::max(this->Result.Bound, e);
  }
}

void Decimator::Queue(std::uint32_t v)
{
  for (const std::uint32_t u : this->Live.Neighbours(v))
  {
    Candidate c;
    c.From = v;
    c.To = u;
    c.Stamp = this->Stamp[v];
    const Vec3 move = this->Live.P[u] - this->Live.P[v];
    c.Length = Norm(move);
    for (const std::uint32_t t : this->Live.Around[v])
    {
      if (!Holds(this->Live.Triangles[t], u))
      {
        c.Cost = std::max(c.Cost, std::fabs(Dot(this->Live.Normal(this->Live.Triangles[t]), move)));
      }
    }
    this->Heap.push(c);
  }
}

void Decimator::Apply(const Collapse& c, double bound)
{
  this->Live.Apply(c);
  for (const std::uint32_t t : c.Kept)
  {
    this->Bounds[t] = bound;
  }
  this->Error.Commit(c);
  ++this->Result.Collapses;
  // Every vertex whose star changed is queued again.
  std::vector<std::uint32_t> changed = this->Live.Neighbours(c.To);
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
  if (!this->Live.Describe(c) || !this->Live.LinkConditionHolds(c))
  {
    e.Outcome = Verdict::Link;
    return e;
  }
  // (Features: the input's sharp creases where S is known, else the
  // surface's own dihedral angles and labels - header, Features.)
  const bool byDihedral = !this->Error.AgainstTheMesh();
  if (byDihedral && !MovesAlongFeatures(this->Live, c))
  {
    e.Outcome = Verdict::Feature;
    return e;
  }
  if (!this->Live.KeepsShape(c))
  {
    e.Outcome = Verdict::Shape;
    return e;
  }
  const bool keepsFeatures = byDihedral
    ? MakesNoFeature(this->Live, c) && KeepsFeatures(this->Live, c)
    : this->Creases.KeepsFollowed(
        this->Live, c, this->Parameters.Tolerance, this->Slack, scratch.Sharp, scratch.Certificate.Triangles);
  if (!keepsFeatures)
  {
    e.Outcome = Verdict::Feature;
    return e;
  }
  e.Bound = this->Error.Certify(c, scratch.Certificate);
  if (!(e.Bound <= this->Parameters.Tolerance))
  {
    e.Outcome = Verdict::Error;
    return e;
  }
  VisitMarks& triangles = scratch.Certificate.Triangles;
  const bool embedded = !MeetsAnother(this->Live, c, triangles) && !SweepsOverAnother(this->Live, c, triangles);
  e.Outcome = embedded ? Verdict::Certified : Verdict::Embedding;
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
  const std::vector<std::uint32_t>& star = this->Live.Around[c.From];
  Box3 read = TriangleBox(this->Live.P, this->Live.Triangles[star.front()]);
  for (const std::uint32_t t : star)
  {
    read = Union(read, TriangleBox(this->Live.P, this->Live.Triangles[t]));
  }
  Box3 written = read;
  // (Grown as Examine grows its boxes, one tolerance at a time, so that
  // every box it queries lies in `read` to the last rounding.)
  read = GrownBy(GrownBy(read, this->Parameters.Tolerance), this->Parameters.Tolerance);
  for (const Box3& other : this->WrittenBoxes)
  {
    if (read.Overlaps(other))
    {
      return false;
    }
  }
  for (const std::uint32_t t : star)
  {
    for (const std::uint32_t v : this->Live.Triangles[t])
    {
      for (const std::uint32_t o : this->Live.Around[v])
      {
        written = Union(written, TriangleBox(this->Live.P, this->Live.Triangles[o]));
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
    if (c.Stamp != this->Stamp[c.From] || this->Live.Around[c.From].empty() || this->Live.Around[c.To].empty())
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
  for (std::uint32_t v = 0; v < this->Live.Around.size(); ++v)
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
        const Examined again = this->Examine(batch[i].From, batch[i].To, *marks);
        const bool same = again.Outcome == e.Outcome &&
          (e.Outcome != Verdict::Certified || (again.Bound == e.Bound && again.What.Witnesses == e.What.Witnesses));
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
  const bool hasLabels = this->Labels.size() == this->Live.Triangles.size();
  for (std::size_t t = 0; t < this->Live.Triangles.size(); ++t)
  {
    if (!this->Live.Alive[t])
    {
      continue;
    }
    Triangle kept = this->Live.Triangles[t];
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
}

} // namespace

DecimationResult DecimateCertified(TriangleMesh& mesh, std::vector<double>& bounds,
  ReleasableArray<std::int32_t>& labels, const DecimationParameters& parameters, const ExactMesh& surface,
  const ParallelFor& parallelFor)
{
  // (The extraction makes closed manifolds of embedded surfaces whose cells
  // all have patches, the caller's condition; checked here all the same - a
  // pass over the edges and vertex links, a few percent of the extraction -
  // since on anything else the link condition would not mean what it says.)
  const TopologyReport premise = ComputeTopologyReport(mesh, parallelFor);
  if (!premise.Closed || !premise.Manifold || !premise.Oriented)
  {
    DecimationResult refused;
    refused.TrianglesBefore = refused.TrianglesAfter = mesh.Triangles.size();
    refused.NotAClosedManifold = true;
    for (const double e : bounds)
    {
      refused.Bound = std::max(refused.Bound, e);
    }
    return refused;
  }
  Decimator decimator(mesh, bounds, labels, parameters, surface);
  decimator.Run(parallelFor);
  decimator.Compact();
  return decimator.Result;
}

} // namespace tpc
