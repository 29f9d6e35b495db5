// Which collapses keep the surface's features (CertifiedDecimation.h,
// Features): the input's sharp creases where S is one mesh, else the
// surface's own feature edges (dihedral angles and solid labels).
#pragma once

#include "LiveSurface.h"
#include "MeshSolid.h"
#include "SharpCreases.h"

#include <vector>

namespace tpc
{

/// A vertex on no feature edge may move to any neighbour; one on exactly
/// two only along one of them (its crease's polyline loses a vertex and
/// stays a chain); corners and ends never.
bool MovesAlongFeatures(const LiveSurface& surface, const Collapse& c);
/// Every feature edge after `c` is the image of one before.
bool MakesNoFeature(const LiveSurface& surface, const Collapse& c);
/// Every feature edge of the star but the one moved along keeps being one
/// (as its image).
bool KeepsFeatures(const LiveSurface& surface, const Collapse& c);

/// S's sharp creases (SharpCreases.h), and the rule that every point of one
/// followed before a collapse stays followed after it.
class SharpCreaseRule
{
public:
  /// `mesh`'s creases of SharpCreaseAngle or more, listed in a grid of
  /// buckets `bucketWidth` wide from `origin`.
  SharpCreaseRule(const MeshSolid& mesh, const Vec3& origin, double bucketWidth);
  /// No sharp crease: no rule.
  SharpCreaseRule(const Vec3& origin, double bucketWidth);

  /// Every point of a sharp crease within `tolerance` of a feature edge
  /// that `c` removes (gone, or no longer bent) stays within `tolerance`
  /// (less the rounding `slack`) of a feature edge after it.
  bool KeepsFollowed(const LiveSurface& surface, const Collapse& c, double tolerance, double slack,
    VisitMarks& creaseMarks, VisitMarks& triangleMarks) const;

private:
  std::vector<EdgeSegment> Sharp;
  TriangleGrid Grid;
};

} // namespace tpc
