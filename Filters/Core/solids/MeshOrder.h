// The order of an input mesh's triangles and vertices in memory.
//
// Why it matters. A cell's tests walk its list of the mesh's triangles
// (CsgExpression's pruning, edge crossings, S_C, the star test), each list
// in the mesh's order; so do the ray casts of the inside test. Where
// consecutive triangles lie near each other, a cell's list reads memory in
// runs; where the order has no locality - armadillo's (a scan): consecutive
// triangles a quarter of the diagonal apart, their vertices a thousand
// entries apart - every triangle and vertex read is a cache miss. Measured
// (2026-12-06): armadillo reordered so takes 0.87, 0.93 and 0.95 of the
// time at 1/64, 1/128 and 1/256 (2 threads; with 1.4 % more instructions at
// 1/64 - other ties, below), CGAL's knots 0.95 (one thread, 1/64); meshes
// exported in a local order - a CAD part's triangles patch by patch: the
// turbine, fandisk, couplingdown, whose consecutive triangles are about an
// edge apart - took 1.00-1.07 of the time reordered (one thread, 1/64). So
// only a mesh whose order is not local (InLocalOrder) is reordered.
//
// The reordering changes no geometry: the same points and triangles, each
// triangle's corners in the same order (its orientation and its edges'
// numbering kept), renamed. What the filter computes from the mesh is the
// same up to the order in which equal candidates are met (sums over a
// cell's list, ties): the surfaces are as valid, triangle counts within a
// few in ten thousand (armadillo at 1/64 and 1/128: 9 378 and 17 408 ->
// 9 378 and 17 420).
#pragma once

#include "Parallel.h"
#include "Vector3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tpc
{

/// Whether the triangles `triangles` over `points` come in a local order:
/// the median distance between consecutive triangles' centroids is at most
/// LocalOrderJumps times the median of their longest edges.
bool InLocalOrder(const std::vector<Vec3>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles);

/// (Armadillo's ratio is 38, CGAL's knots' 8.5 and 9.8; its other demo
/// meshes' at most 3.5, most below 1.)
constexpr double LocalOrderJumps = 4.0;

/// Reorders `triangles` along a Morton curve through their centroids (ties
/// in their order), and `points` in the order the reordered triangles first
/// use them (points no triangle uses last, in their order); renames the
/// corners of `triangles` and the entries of `neighbours` (the triangle
/// across each edge, or `none`; empty for none given) to match. The codes
/// and their sort in parallel (the same order on any number of threads: the
/// keys are distinct).
void OrderAlongMortonCurve(std::vector<Vec3>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
  std::vector<std::array<std::uint32_t, 3>>& neighbours, std::uint32_t none,
  const ParallelFor& parallelFor = SequentialFor);

} // namespace tpc
