// What TopologyGuaranteed rests on (README: the guarantee). Each condition
// is necessary: the output has the exact surface's components and genus,
// lies within the tolerance of it, and is the boundary of the solid, only
// when all hold; Contour.cxx (DecideGuarantee) gathers them and says which
// failed. Kept as one conjunction in one place so that a condition added to
// the guarantee - as Outward was (SolidBoundary.h) - is added to the flag,
// and a test holds every one of them necessary (TestTopologyGuarantee.cxx).
#pragma once

namespace tpc
{

struct GuaranteeConditions
{
  /// The inputs meet the method's assumptions (closed, oriented, without
  /// self-intersection; implicit functions of the supported kinds).
  bool AssumptionsMet = false;
  /// Every surface cell passed the complex-cell and star-shaped tests (none
  /// left by a limit, none between surfaces too close to resolve).
  bool EveryCellResolved = false;
  /// Every cell's crossings closed into loops.
  bool LoopsConsistent = false;
  /// No two triangles of the output meet other than in a shared edge or
  /// vertex (exact check: SurfaceEmbedding.h).
  bool Embedded = false;
  /// The proven Hausdorff bound is within the tolerance.
  bool WithinTolerance = false;
  /// One run holds the whole surface, or its pieces agreed (a collective
  /// split run).
  bool WholeSurface = false;
  /// The surface is closed, manifold and consistently oriented, or empty.
  bool ClosedOrientedManifold = false;
  /// Each component is oriented outward with respect to the solid it
  /// bounds, or the surface is empty (SolidBoundary.h).
  bool Outward = false;
};

/// TopologyGuaranteed: all of them.
inline bool TopologyGuaranteed(const GuaranteeConditions& c)
{
  return c.AssumptionsMet && c.EveryCellResolved && c.LoopsConsistent && c.Embedded && c.WithinTolerance &&
    c.WholeSurface && c.ClosedOrientedManifold && c.Outward;
}

} // namespace tpc
