// The certified error of a collapse (CertifiedDecimation.h: Error, Against
// the mesh, Witnesses): where the scene is one input mesh S, against S
// itself, both ways, with the witnesses that spare (b) most of S; elsewhere
// through each triangle's bound, composed by the branch and bound's offsets.
#pragma once

#include "CertifiedDecimation.h"
#include "LiveSurface.h"
#include "PolygonHausdorff.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace tpc
{

/// The marks a certificate's searches use (one set per thread).
struct CertificateMarks
{
  VisitMarks Triangles; ///< the surface's live triangles
  VisitMarks Star;      ///< the star's triangles
  VisitMarks Surface;   ///< S's triangles
};

class ErrorCertificates
{
public:
  /// `live`, `bounds` (e_t per triangle) and `parameters` are read as they
  /// are when Certify runs; `surface` is S where known. `extent` is the
  /// surface's points' box: S's triangles are listed in a grid of buckets
  /// `bucketWidth` wide from its corner, and the distances' rounding slack
  /// is taken of its coordinates (MeshCellError.h: RoundingSlackFor; the polygons'
  /// PolygonSet::SetSlackMagnitude).
  ErrorCertificates(const LiveSurface& live, const std::vector<double>& bounds,
    const DecimationParameters& parameters, const ExactMesh& surface, const Box3& extent, double bucketWidth);

  /// The bound of c's made triangles (rounding slack included), or +inf
  /// when it is not certified within the tolerance. Against the mesh it
  /// also sets c.Witnesses, which Commit keeps once c is applied.
  double Certify(Collapse& c, CertificateMarks& marks) const;
  /// c was applied: its witnesses hold.
  void Commit(const Collapse& c);
  bool AgainstTheMesh() const { return this->Surface.Mesh != nullptr; }

private:
  double ThroughBounds(const Collapse& c) const;
  double AgainstMesh(Collapse& c, CertificateMarks& marks) const;
  /// S's triangles whose boxes overlap `box`, in `near` (in the grid's order).
  void NearSurface(const Box3& box, std::vector<std::uint32_t>& near, VisitMarks& marks) const;
  /// S's triangles overlapping `region` that no live triangle outside the
  /// star witnesses (CertifiedDecimation.h, Witnesses): whole where they lie
  /// in `region`, else clipped to it and fanned; `from` names each piece's
  /// triangle and whether it is whole.
  void UnwitnessedNear(const Collapse& c, const Box3& region, std::vector<SourceTriangle>& pieces,
    std::vector<std::pair<std::uint32_t, bool>>& from, CertificateMarks& marks) const;

  const LiveSurface& Live;
  const std::vector<double>& Bounds;
  const DecimationParameters& Parameters;
  ExactMesh Surface;
  TriangleGrid SurfaceGrid;
  /// S's triangles as polygons, in order, and prepared as the targets of the
  /// made triangles' branch and bounds (AgainstMesh): built with the
  /// certificates, whether or not a collapse is then tried (about 330 bytes
  /// per triangle of S). SurfaceTargets refers to SurfacePolygons: neither
  /// is copied or moved (HausdorffTargets cannot be).
  PolygonSet SurfacePolygons;
  HausdorffTargets SurfaceTargets;
  /// Per triangle of S: a live triangle within the tolerance of all of it,
  /// or None.
  std::vector<std::uint32_t> Witness;
  double Slack;
  double SlackMagnitude;
};

} // namespace tpc
