// Vertices split along the creases of an indexed triangle mesh, for shading.
//
// A renderer interpolates point normals across each triangle, so a point
// normal averaged over the triangles on both sides of a crease (a box's edge,
// a CAD part's rim) shades both faces as if the edge were rounded: a halo as
// wide as the triangles beside it. vtkPolyDataNormals' answer is to give the
// point one copy per wedge of triangles between creases, each with its
// wedge's normal; this does the same on the extracted surface, which stays
// the same point set: every copy keeps its original's position, so the
// surface and everything the topology report says of it are unchanged - only
// the triangles' vertex ids differ, and `SurfacePoint` maps every point back
// to the closed surface's point (Manifold's MeshGL keeps such a merge map for
// the same reason).
//
// Hand-written rather than vtkPolyDataNormals: the crossing vertices keep the
// exact surface's gradient as their normal where they are not split (a
// filter would replace it by an average of the output's coarse triangles),
// and the core has no VTK.
#pragma once

#include "TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// An edge of two triangles is a crease when their normals differ by at least
/// `creaseAngleDegrees`. Each point whose triangles are separated by two or
/// more creases into several wedges gets one point per wedge (the first
/// keeps its id, the others are appended, in order of their first triangle),
/// with the wedge's angle-weighted normal; triangles are renumbered.
/// `surfacePoint` receives, per point of the result, the id it had before
/// (the identity on the points that were there). Points with one wedge keep
/// their id and normal; an edge of other than two triangles separates wedges
/// as a crease does.
void SplitAtCreases(TriangleMesh& mesh, double creaseAngleDegrees, std::vector<std::uint32_t>& surfacePoint);

} // namespace tpc
