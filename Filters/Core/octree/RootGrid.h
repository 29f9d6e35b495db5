// The root grid of the octree forest and the integer lattice of its finest
// level. Every corner, edge and cell is addressed by integer lattice
// coordinates at level MaxDepth; world coordinates are computed from them by
// one formula, so cells sharing a corner see bit-identical coordinates.
#pragma once

#include "Vector3.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace tpc
{

/// One axis' coordinate on the lattice of the finest level (MaxDepth).
using LatticeIndex = std::uint64_t;

/// Lattice coordinates use 42 bits per axis, so the lattice reaches 2^-41 of
/// a single root cell; how deep a grid actually goes is also bounded by the
/// doubles its coordinates are written in (DoublePrecisionDepth). A point key
/// packs the three coordinates into 126 bits of one 128-bit integer, leaving
/// two bits for an axis (sub-edge and line keys). GCC and Clang provide the
/// 128-bit integer on every 64-bit target; a compiler without it would need a
/// two-word struct with the same operators.
constexpr int LatticeBits = 42;
constexpr LatticeIndex LatticeLimit = LatticeIndex(1) << LatticeBits;

#if !defined(__SIZEOF_INT128__)
#error "TopologyPreservingContour's lattice keys need a 128-bit integer (GCC or Clang on a 64-bit target)"
#endif
__extension__ typedef unsigned __int128 LatticeKey;
using PointKey = LatticeKey;

inline PointKey MakePointKey(LatticeIndex x, LatticeIndex y, LatticeIndex z)
{
  return static_cast<PointKey>(x) | (static_cast<PointKey>(y) << LatticeBits) |
    (static_cast<PointKey>(z) << (2 * LatticeBits));
}

inline void SplitPointKey(PointKey k, LatticeIndex p[3])
{
  const PointKey mask = LatticeLimit - 1;
  p[0] = static_cast<LatticeIndex>(k & mask);
  p[1] = static_cast<LatticeIndex>((k >> LatticeBits) & mask);
  p[2] = static_cast<LatticeIndex>((k >> (2 * LatticeBits)) & mask);
}

/// A point key with an axis in its two spare bits: a lattice sub-edge from
/// the point along the axis, or (with the axis' own coordinate zeroed) the
/// lattice line along the axis.
inline LatticeKey WithAxis(PointKey point, int axis)
{
  return (point << 2) | static_cast<LatticeKey>(axis);
}
inline int AxisOf(LatticeKey k)
{
  return static_cast<int>(k & 3);
}
inline PointKey PointOf(LatticeKey k)
{
  return k >> 2;
}
/// The lattice line along `axis` through p.
inline LatticeKey LineKey(const LatticeIndex p[3], int axis)
{
  LatticeIndex q[3] = { p[0], p[1], p[2] };
  q[axis] = 0;
  return WithAxis(MakePointKey(q[0], q[1], q[2]), axis);
}

/// A well-mixed hash of a 128-bit key (for hash tables keyed by lattice points).
inline std::size_t HashKey(LatticeKey key)
{
  std::uint64_t k = static_cast<std::uint64_t>(key) ^ (static_cast<std::uint64_t>(key >> 64) * 0x9E3779B97F4A7C15ULL);
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdULL;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ULL;
  k ^= k >> 33;
  return static_cast<std::size_t>(k);
}
struct LatticeKeyHash
{
  std::size_t operator()(LatticeKey k) const { return HashKey(k); }
};

struct RootGrid
{
  Vec3 Origin;
  double RootSize = 1.0;         ///< edge length of each (cubic) root cell
  int Dims[3] = { 1, 1, 1 };     ///< number of root cells (trees) per axis
  int MaxDepth = 0;              ///< finest level; lattice spacing = RootSize / 2^MaxDepth

  int TreeCount() const { return Dims[0] * Dims[1] * Dims[2]; }
  /// Index of the tree at root coordinates (i, j, k), i fastest; and back.
  int TreeIndex(int i, int j, int k) const { return i + Dims[0] * (j + Dims[1] * k); }
  void TreeCoordinates(int t, int ijk[3]) const
  {
    ijk[0] = t % Dims[0];
    ijk[1] = (t / Dims[0]) % Dims[1];
    ijk[2] = t / (Dims[0] * Dims[1]);
  }

  /// World coordinate of lattice index `i` (at level MaxDepth) on an axis.
  /// Why this is enough for exact predicates at any depth: the coordinate is
  /// one formula of the index, so every cell sharing a lattice point sees the
  /// same double; it is monotone in i (an exact integer-to-double conversion,
  /// i < 2^53, then a product by a positive constant and a sum, each rounded
  /// monotonically), so a child's box lies in its parent's and neighbours'
  /// boxes do not overlap; and MakeRootGrid keeps the lattice spacing at
  /// least 2^4 ulps of every coordinate (DoublePrecisionDepth), so distinct
  /// lattice points stay distinct doubles and no cell is flat. The exact
  /// predicates then decide on these doubles as given.
  double Coordinate(int axis, LatticeIndex i) const
  {
    return Origin[axis] + static_cast<double>(i) * Spacing();
  }
  /// The lattice spacing RootSize / 2^MaxDepth, exactly (a product by a
  /// power of two), built from the exponent's bits: Coordinate is on every
  /// hot path, and std::ldexp is a library call.
  double Spacing() const
  {
    if (MaxDepth > 1022 || MaxDepth < -1022)
    {
      return std::ldexp(RootSize, -MaxDepth);
    }
    const std::uint64_t bits = static_cast<std::uint64_t>(1023 - MaxDepth) << 52;
    double scale;
    std::memcpy(&scale, &bits, sizeof scale);
    return RootSize * scale;
  }
  Vec3 Point(const LatticeIndex p[3]) const
  {
    return { Coordinate(0, p[0]), Coordinate(1, p[1]), Coordinate(2, p[2]) };
  }
  Vec3 Point(PointKey k) const
  {
    LatticeIndex p[3];
    SplitPointKey(k, p);
    return Point(p);
  }
  /// Lattice box of a cell at `level` with integer coordinates ijk at that level.
  Box3 CellBox(int level, const LatticeIndex ijk[3]) const
  {
    const int shift = MaxDepth - level;
    Box3 b;
    for (int a = 0; a < 3; ++a)
    {
      b.lo[a] = Coordinate(a, ijk[a] << shift);
      b.hi[a] = Coordinate(a, (ijk[a] + 1) << shift);
    }
    return b;
  }
  double CellDiagonal(int level) const
  {
    return std::ldexp(RootSize, -level) * 1.7320508075688772;
  }
};

/// The level at which cells covering `domain` (its largest width, as the root
/// size) have a diagonal of at most `tolerance`: where the Hausdorff size
/// test stops refining (0 for a non-positive tolerance).
int ToleranceLevel(const Box3& domain, double tolerance);

/// Chooses the root grid: cubic root cells covering `domain`, sized so that
/// some level has cells whose diagonal is exactly the tolerance (no finer
/// than needed), and the finest lattice the keys support. `placement` picks
/// one of several generic lattice offsets.
RootGrid MakeRootGrid(const Box3& domain, double hausdorffTolerance, int maximumDepth, int placement = 0);

/// Face refinement (FaceRefinement.h) samples cell faces down to this many
/// levels below the deepest cells MaximumDepth allows, never below the
/// lattice: deep enough to separate the crossings of a surface on a deepest
/// cell's edge, and the depth the lattice placements were measured with (a
/// 20-bit lattice under cells of depth 16). The lattice itself goes deeper,
/// so raising MaximumDepth takes the samples with it.
constexpr int SampleLevelsBelowDeepestCells = 3;

/// The deepest level face refinement samples for `maximumDepth` on `grid`.
inline int SampleDepth(const RootGrid& grid, int maximumDepth)
{
  const int deepestCells = maximumDepth < grid.MaxDepth ? maximumDepth : grid.MaxDepth;
  const int samples = deepestCells + SampleLevelsBelowDeepestCells;
  return samples < grid.MaxDepth ? samples : grid.MaxDepth;
}

/// Largest MaximumDepth the lattice keys support for a root grid of `dims`.
int MaximumSupportedDepth(const int dims[3]);

/// Largest depth at which the lattice spacing of a root cell of `rootSize`
/// is still at least 2^4 ulps of every coordinate of `box` (see
/// RootGrid::Coordinate).
int DoublePrecisionDepth(const Box3& box, double rootSize);

} // namespace tpc
