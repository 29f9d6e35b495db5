// Exact signs of the field at lattice points, evaluated once per point and
// shared by the up to eight cells meeting there (open addressing on the
// packed point key). Inserts happen between parallel phases; lookups may run
// concurrently.
#pragma once

#include "RootGrid.h"

#include <cstdint>
#include <vector>

namespace tpc
{

class LatticeSignTable
{
public:
  /// -1: unknown, 0: outside, 1: inside.
  int Find(PointKey key) const
  {
    if (this->Keys.empty())
    {
      return -1;
    }
    const std::size_t mask = this->Keys.size() - 1;
    for (std::size_t i = Hash(key) & mask;; i = (i + 1) & mask)
    {
      const LatticeKey k = this->Keys[i];
      if (k == 0)
      {
        return -1;
      }
      if (k == key + 1)
      {
        return this->Inside[i];
      }
    }
  }

  void Insert(PointKey key, bool inside)
  {
    if (2 * (this->Count + 1) > this->Keys.size())
    {
      this->Grow();
    }
    const std::size_t mask = this->Keys.size() - 1;
    for (std::size_t i = Hash(key) & mask;; i = (i + 1) & mask)
    {
      if (this->Keys[i] == 0)
      {
        this->Keys[i] = key + 1;
        this->Inside[i] = inside ? 1 : 0;
        ++this->Count;
        return;
      }
      if (this->Keys[i] == key + 1)
      {
        return;
      }
    }
  }

  std::size_t Size() const { return this->Count; }
  std::size_t MemoryBytes() const { return this->Keys.size() * (sizeof(LatticeKey) + 1); }

private:
  static std::size_t Hash(PointKey k) { return HashKey(k); }

  void Grow()
  {
    std::vector<LatticeKey> oldKeys;
    std::vector<std::uint8_t> oldInside;
    oldKeys.swap(this->Keys);
    oldInside.swap(this->Inside);
    const std::size_t size = oldKeys.empty() ? 1024 : 2 * oldKeys.size();
    this->Keys.assign(size, 0);
    this->Inside.assign(size, 0);
    this->Count = 0;
    for (std::size_t i = 0; i < oldKeys.size(); ++i)
    {
      if (oldKeys[i] != 0)
      {
        this->Insert(oldKeys[i] - 1, oldInside[i] != 0);
      }
    }
  }

  std::vector<LatticeKey> Keys; // key + 1; 0 marks an empty slot
  std::vector<std::uint8_t> Inside;
  std::size_t Count = 0;
};

} // namespace tpc
