// The topology report of a surface split into pieces (issue 7: one piece per
// MPI rank), without gathering the surface.
//
// The pieces of a split run meet at seams with bit-identical vertices
// (ForestPartition.h): each piece's surface is open exactly there, and a
// seam edge is a boundary edge of the two pieces on either side, in opposite
// directions. So each piece sends only its counts and its boundary edges
// (with the local component each belongs to), and every piece combines them:
// V and E are summed minus the seam vertices and edges counted twice, F is
// summed, components are joined across shared seam vertices, and the surface
// is closed when every boundary edge meets its twin.
#pragma once

#include "TopologyReport.h"
#include "TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// What one piece contributes: local counts and its boundary edges.
struct PieceSeams
{
  std::int64_t Vertices = 0;
  std::int64_t Edges = 0;
  std::int64_t Faces = 0;
  std::int64_t Components = 0;
  std::int64_t NonManifoldEdges = 0;
  /// Interior edges whose two triangles run them the same way.
  std::int64_t MisorientedEdges = 0;
  /// Per boundary edge: from and to (x, y, z each), in its triangle's order.
  std::vector<double> BoundaryEdges;
  /// Local component (0 .. Components - 1) of each boundary edge.
  std::vector<std::int64_t> BoundaryComponents;

  /// Flat form for sending: counts, edge count, then per edge 6 coordinates
  /// and the component (doubles hold integers up to 2^53 exactly).
  std::vector<double> Serialize() const;
  /// Reads pieces back from consecutive serialized forms.
  static std::vector<PieceSeams> DeserializeAll(const std::vector<double>& data);
};

PieceSeams DescribePiece(const TriangleMesh& piece);

/// Components, Euler characteristic, genus, closed and manifold (over edges)
/// of the union of the pieces.
TopologyReport CombinePieces(const std::vector<PieceSeams>& pieces);

} // namespace tpc
