// Disjoint sets over 0 .. n-1 (path halving): components of meshes, of vertex
// links, of pieces joined across seams.
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace tpc
{

struct UnionFind
{
  std::vector<std::uint32_t> Parent;

  explicit UnionFind(std::size_t n)
    : Parent(n)
  {
    std::iota(Parent.begin(), Parent.end(), 0u);
  }
  /// n singletons again, keeping the storage (for reuse in a loop).
  void Reset(std::size_t n)
  {
    Parent.resize(n);
    std::iota(Parent.begin(), Parent.end(), 0u);
  }
  std::uint32_t Find(std::uint32_t x)
  {
    while (Parent[x] != x)
    {
      Parent[x] = Parent[Parent[x]];
      x = Parent[x];
    }
    return x;
  }
  /// Joins the sets of a and b; false if they were one set already.
  bool Join(std::uint32_t a, std::uint32_t b)
  {
    const std::uint32_t ra = this->Find(a), rb = this->Find(b);
    this->Parent[ra] = rb;
    return ra != rb;
  }
};

} // namespace tpc
