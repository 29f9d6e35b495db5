// Is the extracted surface embedded - no self-intersection, no self-touching?
// Checked exactly on the output, as part of the topology guarantee.
//
// A closed manifold triangle mesh is an embedded surface when no two of its
// vertices have the same coordinates and every two triangles meet only in
// the vertices or the edge they share (then distinct points of the abstract
// surface land on distinct points of space). Both are decided exactly: vertex
// coordinates are compared as doubles, triangle pairs with exact predicates
// (SelfIntersection.h: touching counts as meeting, coplanar pairs included),
// and triangles with three collinear vertices are counted as failures too.
//
// Which pairs can meet: every triangle is first verified to lie in the closed
// box of its octree cell (its three vertices do; a box is convex). Two
// triangles of cells whose closed boxes are apart are then apart, so only
// pairs from one cell, or from two leaves sharing a face, an edge or a corner,
// need a test - a few neighbours' patches per cell instead of a search over
// the whole surface, whatever the triangles' sizes. A triangle outside its
// cell would break that argument; it is counted as a failure (the extraction
// never makes one: LoopTriangulation.h).
#pragma once

#include "AdaptiveOctree.h"
#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

struct EmbeddingReport
{
  std::size_t ImproperPairs = 0;         ///< triangle pairs meeting other than in what they share
  std::size_t CoincidentVertices = 0;    ///< vertices with the coordinates of an earlier one
  std::size_t DegenerateTriangles = 0;   ///< three collinear vertices
  std::size_t TrianglesOutsideCells = 0; ///< a vertex outside the triangle's cell box
  std::size_t PairsTested = 0;           ///< exact pair tests run (pairs around a proven star: none, EmbeddedStars.h)
  /// Octree nodes whose patches take part in a failure (each once, sorted).
  std::vector<std::uint32_t> Cells;
  bool Aborted = false;

  bool Embedded() const
  {
    return !this->Aborted && this->ImproperPairs == 0 && this->CoincidentVertices == 0 &&
      this->DegenerateTriangles == 0 && this->TrianglesOutsideCells == 0;
  }
};

/// Checks `mesh` as extracted from `tree` (TriangleCell in node order, as
/// ExtractSurface writes it). Runs in parallel, in chunks reporting
/// progress; an abort returns a report with Aborted set.
EmbeddingReport CheckEmbedding(const AdaptiveOctree& tree, const TriangleMesh& mesh,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// In a piece of a split run (ForestPartition.h), CheckEmbedding sees the
/// piece's own triangles only. Pieces own disjoint sets of trees and every
/// triangle lies in its cell, so triangles of two pieces can meet only if
/// their cells touch a tree the other piece owns: these seam triangles, nine
/// coordinates each, are what the pieces exchange.
std::vector<double> SeamTriangles(const AdaptiveOctree& tree, const TriangleMesh& mesh);

/// Improper pairs between two pieces' seam triangles (exact). Vertices at the
/// same coordinates are one vertex: the pieces' seam vertices are
/// bit-identical, and no two vertices of one piece coincide once
/// CheckEmbedding has passed.
std::size_t CountImproperSeamPairs(const std::vector<double>& a, const std::vector<double>& b);

} // namespace tpc
