// The root grid of the octree forest and the integer lattice of its finest
// level. Every corner, edge and cell is addressed by integer lattice
// coordinates at level MaxDepth; world coordinates are computed from them by
// one formula, so cells sharing a corner see bit-identical coordinates.
#pragma once

#include "Vector3.h"

#include <cstdint>

namespace tpc
{

/// Lattice coordinates use 20 bits per axis: a point key packs three of them.
constexpr int LatticeBits = 20;
constexpr std::uint32_t LatticeLimit = 1u << LatticeBits;

using PointKey = std::uint64_t;

inline PointKey MakePointKey(std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
  return static_cast<PointKey>(x) | (static_cast<PointKey>(y) << LatticeBits) |
    (static_cast<PointKey>(z) << (2 * LatticeBits));
}

inline void SplitPointKey(PointKey k, std::uint32_t p[3])
{
  const PointKey mask = LatticeLimit - 1;
  p[0] = static_cast<std::uint32_t>(k & mask);
  p[1] = static_cast<std::uint32_t>((k >> LatticeBits) & mask);
  p[2] = static_cast<std::uint32_t>((k >> (2 * LatticeBits)) & mask);
}

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
  double Coordinate(int axis, std::uint32_t i) const
  {
    return Origin[axis] + static_cast<double>(i) * std::ldexp(RootSize, -MaxDepth);
  }
  Vec3 Point(const std::uint32_t p[3]) const
  {
    return { Coordinate(0, p[0]), Coordinate(1, p[1]), Coordinate(2, p[2]) };
  }
  Vec3 Point(PointKey k) const
  {
    std::uint32_t p[3];
    SplitPointKey(k, p);
    return Point(p);
  }
  /// Lattice box of a cell at `level` with integer coordinates ijk at that level.
  Box3 CellBox(int level, const std::uint32_t ijk[3]) const
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

/// Largest MaximumDepth the lattice supports for a root grid of `dims`.
int MaximumSupportedDepth(const int dims[3]);

} // namespace tpc
