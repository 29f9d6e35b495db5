// Crack patching (paper 4.3): the loops the surface draws on one leaf's
// boundary, sampled exactly as every neighbour samples the faces it shares.
//
// A leaf that meets the surface walks its six faces at the finest resolution
// present on them: a face shared with smaller neighbours is split into their
// faces (with their face refinements), and every leaf corner and refinement
// point on its faces and edges is a sample - the same points every other
// cell touching them gathers. On each tile, every run of inside samples along
// the tile's boundary is cut off by one segment between the two crossings
// bounding it (BoundaryLoops.h); both cells sharing a tile compute the same
// segments from the same samples, and a crossing is named by the finest
// lattice sub-edge holding it, so no crack can appear and every edge of the
// output has exactly two triangles - whether or not the cell passed the
// tests. A tile shared with an exact cell carries the mesh's exact trace
// instead of its sampled chord (ExactCell.h); a crease tile shared by two
// cells of the same mesh, its chord bent through the crease's crossing
// (CreaseCrossing.h).
#pragma once

#include "AdaptiveOctree.h"
#include "BoundaryLoops.h"

#include <cstddef>

namespace tpc
{

class FaceDecisionCache; // (FaceDecisionCache.h)

/// The samples on the boundary of leaf `cell`: its faces' tiles from
/// whichever side is finer, and every sample point on them.
CellBoundary GatherCellBoundary(const AdaptiveOctree& tree, std::size_t cell);

/// The loops of leaf `cell` traced from its boundary's samples
/// (MarkedCellBoundary); for an exact cell, its polygons (ExactCell.h).
BoundaryLoopSet CellLoops(const AdaptiveOctree& tree, std::uint32_t cell, const PrimitiveSet& primitives,
  FaceDecisionCache* faceDecisions = nullptr);

/// The boundary leaf `cell` (not exact) traces its loops from: its samples
/// (GatherCellBoundary), the tiles shared with an exact cell carrying the
/// mesh's trace, and its crease tiles marked - the tiles its loops' chords
/// cross, for their deltas (MeshCellError.h: MeasureChords).
CellBoundary MarkedCellBoundary(const AdaptiveOctree& tree, std::uint32_t cell, const PrimitiveSet& primitives,
  FaceDecisionCache* faceDecisions = nullptr);

} // namespace tpc
