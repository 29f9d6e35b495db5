#include "ErrorCertificates.h"

#include "ConvexPolygons.h"
#include "MeshCellError.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

ErrorCertificates::ErrorCertificates(const LiveSurface& live, const std::vector<double>& bounds,
  const DecimationParameters& parameters, const ExactMesh& surface, const Box3& extent, double bucketWidth)
  : Live(live)
  , Bounds(bounds)
  , Parameters(parameters)
  , Surface(surface)
  , SurfaceGrid(extent.lo, bucketWidth)
  , Slack(RoundingSlackFor(extent.Magnitude(), extent.Diagonal()))
  , SlackMagnitude(extent.Magnitude())
{
  if (surface.Mesh)
  {
    const Vec3* points = surface.Mesh->Points().data();
    const std::vector<Triangle>& triangles = surface.Mesh->Triangles();
    this->SurfacePolygons.SetSlackMagnitude(this->SlackMagnitude);
    this->SurfacePolygons.reserve(triangles.size(), 3 * triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
    {
      this->SurfaceGrid.Insert(t, surface.Mesh->TriangleBounds(t));
      const Triangle& f = triangles[t];
      this->SurfacePolygons.Add({ points[f[0]], points[f[1]], points[f[2]] });
    }
    this->SurfaceTargets.Prepare(this->SurfacePolygons);
    this->Witness.assign(triangles.size(), SingleTargetWitness::None);
  }
}

double ErrorCertificates::Certify(Collapse& c, CertificateMarks& marks) const
{
  return this->Surface.Mesh ? this->AgainstMesh(c, marks) : this->ThroughBounds(c);
}

void ErrorCertificates::NearSurface(const Box3& box, std::vector<std::uint32_t>& near, VisitMarks& marks) const
{
  near.clear();
  marks.Start(this->Surface.Mesh->Triangles().size());
  this->SurfaceGrid.ForEachListed(box, [&](std::uint32_t s) {
    if (marks.First(s) && this->Surface.Mesh->TriangleBounds(s).Overlaps(box))
    {
      near.push_back(s);
    }
  });
}

void ErrorCertificates::UnwitnessedNear(const Collapse& c, const Box3& region, std::vector<SourceTriangle>& pieces,
  std::vector<std::pair<std::uint32_t, bool>>& from, CertificateMarks& marks) const
{
  marks.Star.Start(this->Live.Triangles.size());
  for (const std::vector<std::uint32_t>* part : { &c.Vanishing, &c.Kept })
  {
    for (const std::uint32_t t : *part)
    {
      marks.Star.First(t);
    }
  }
  const Vec3* points = this->Surface.Mesh->Points().data();
  const std::vector<Triangle>& triangles = this->Surface.Mesh->Triangles();
  marks.Surface.Start(triangles.size());
  this->SurfaceGrid.ForEachListed(region, [&](std::uint32_t s) {
    const Triangle& t = triangles[s];
    const Box3& box = this->Surface.Mesh->TriangleBounds(s);
    if (!marks.Surface.First(s) || !box.Overlaps(region))
    {
      return;
    }
    const std::uint32_t w = this->Witness[s];
    if (w != SingleTargetWitness::None && this->Live.Alive[w] && !marks.Star.Visited(w))
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
    AppendAsSources(clipped.data(), clipped.size(), pieces);
    from.resize(pieces.size(), { s, false });
  });
}

double ErrorCertificates::AgainstMesh(Collapse& c, CertificateMarks& marks) const
{
  const double tolerance = this->Parameters.Tolerance;
  const double giveUp = tolerance - this->Slack;
  const std::size_t budget = this->Parameters.CertificateBudget;
  // (a) The made triangles, to S near them: one at a time, each with the
  // whole budget. (A large made triangle on a CAD face needs about a
  // thousand pieces, and a collapse there makes five to ten: with one budget
  // for all, fandisk's large faces refused the same collapses again and
  // again - at 1/128, 155 of 1 039 certificates ran out, 71 % of the pieces
  // evaluated, 3.4 s; one budget each, 0.75 s, 164 -> 162 triangles.) S near
  // them: the triangles whose boxes meet the made triangles' box grown by
  // the tolerance. Where they are few, as polygons of their own, scanned
  // (PolygonHausdorff.h); where they are many, the whole of S is searched in
  // the hierarchy prepared once (SurfaceTargets) - making them polygons and
  // a hierarchy for each collapse was half of armadillo's decimation at
  // 1/64 - with the same decision and bound. A triangle of S whose box
  // misses the grown box is farther than the tolerance less an ulp of the
  // growing - far more than giveUp = tolerance - Slack - from every point of
  // the made triangles. So wherever g over S near them is within giveUp, g
  // over all of S is the same (a minimum over those and others farther), and
  // so is the single-target bound (1); a piece's bound within giveUp is the
  // same, and one above it is above it either way. The search stops at
  // giveUp: pieces within it are settled at once, never queued, and every
  // piece above it is split, in whatever order - so the same pieces are
  // evaluated and settled, with the same values, unless the budget runs out
  // or a vertex is farther than giveUp, which refuses the collapse either
  // way. ("The same" up to the ulp a box test may keep or drop with the
  // order of the visits, PolygonHausdorff.h; bit for bit on every scene
  // compared. Test: PolygonHausdorff.AllTargetsBoundAsTheNearOnesWhereTheSearchStopsAtGiveUp.)
  PolygonSet madeSet;
  madeSet.SetSlackMagnitude(this->SlackMagnitude);
  thread_local std::vector<std::uint32_t> near;
  this->NearSurface(GrownBy(BoxOf(this->Live.P, c.Made), tolerance), near, marks.Surface);
  PolygonSet nearMade;
  const bool few = near.size() < HausdorffTargets::HierarchyFrom;
  if (few)
  {
    nearMade.SetSlackMagnitude(this->SlackMagnitude);
    const Vec3* points = this->Surface.Mesh->Points().data();
    for (const std::uint32_t s : near)
    {
      const Triangle& f = this->Surface.Mesh->Triangles()[s];
      nearMade.Add({ points[f[0]], points[f[1]], points[f[2]] });
    }
  }
  double toSurface = 0.0;
  for (const Triangle& t : c.Made)
  {
    const SourceTriangle made = this->Live.CornersOf(t);
    madeSet.Add(made.data(), made.size());
    toSurface = std::max(toSurface,
      (few ? OneSidedHausdorff({ made }, nearMade, giveUp, giveUp, budget)
           : OneSidedHausdorff({ made }, this->SurfaceTargets, giveUp, giveUp, budget))
        .Upper);
    if (!(toSurface <= giveUp))
    {
      return HUGE_VAL;
    }
  }
  // (b) S where the star was nearest (but where a triangle outside the star
  // witnesses it), to the surface after.
  const Box3 region = GrownBy(BoxOf(this->Live.P, this->Live.StarOf(c)), tolerance);
  std::vector<SourceTriangle> surfacePieces;
  std::vector<std::pair<std::uint32_t, bool>> from;
  this->UnwitnessedNear(c, region, surfacePieces, from, marks);
  PolygonSet after = madeSet;
  std::vector<std::uint32_t> afterIds = c.Kept; // (the made triangles take the kept ones' ids)
  this->Live.ForEachOther(c, GrownBy(region, tolerance), marks.Triangles, [&](std::uint32_t o) {
    const SourceTriangle s = this->Live.CornersOf(this->Live.Triangles[o]);
    after.Add(s.data(), s.size());
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
  return std::max({ toSurface, covered.Upper, witnessed }) + this->Slack;
}

double ErrorCertificates::ThroughBounds(const Collapse& c) const
{
  std::vector<SourceTriangle> before, after;
  std::vector<double> offsets;
  PolygonSet beforeSet, afterSet;
  beforeSet.SetSlackMagnitude(this->SlackMagnitude);
  afterSet.SetSlackMagnitude(this->SlackMagnitude);
  double largest = 0.0;
  for (const std::vector<std::uint32_t>* part : { &c.Vanishing, &c.Kept })
  {
    for (const std::uint32_t t : *part)
    {
      const SourceTriangle s = this->Live.CornersOf(this->Live.Triangles[t]);
      before.push_back(s);
      beforeSet.Add(s.data(), s.size());
      offsets.push_back(this->Bounds[t]);
      largest = std::max(largest, this->Bounds[t]);
    }
  }
  for (const Triangle& t : c.Made)
  {
    const SourceTriangle s = this->Live.CornersOf(t);
    after.push_back(s);
    afterSet.Add(s.data(), s.size());
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
  // (The result is the larger of the two: the first's attained distance
  // lets the second settle its pieces below it without a search,
  // PolygonHausdorff.h, Settled pieces - the same maximum.)
  const HausdorffEstimate near =
    OneSidedHausdorff(after, beforeSet, enough, giveUp, budget, { nullptr, &offsets }, nullptr, covered.Lower);
  if (!(near.Upper <= giveUp))
  {
    return HUGE_VAL;
  }
  return std::max(covered.Upper, near.Upper) + this->Slack;
}

void ErrorCertificates::Commit(const Collapse& c)
{
  for (const auto& [s, w] : c.Witnesses)
  {
    this->Witness[s] = w;
  }
}

} // namespace tpc
