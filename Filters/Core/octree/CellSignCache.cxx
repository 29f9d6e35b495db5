#include "CellSignCache.h"

#include <cassert>

namespace tpc
{

bool CellSignCache::Inside(PointKey key)
{
  const int known = this->Known(key);
  if (known >= 0)
  {
    return known == 1;
  }
  const bool in = this->Expression.IsInside(this->Grid.Point(key), this->Primitives);
  this->Remember(key, in);
  return in;
}

void CellSignCache::Learn(PointKey key, bool inside)
{
  const int known = this->Known(key);
  assert((known < 0 || (known == 1) == inside) && "an exact sign is the same wherever it was evaluated");
  if (known < 0)
  {
    this->Remember(key, inside);
  }
}

int CellSignCache::Known(PointKey key)
{
  const int known = this->Global.Find(key);
  if (known >= 0)
  {
    return known;
  }
  // A few fresh points are found fastest by a scan; a cell that evaluates
  // many (a face refined along a long sliver) switches to a hash table, or
  // its lookups would grow quadratically.
  constexpr std::size_t ScanLimit = 32;
  if (this->Fresh.size() <= ScanLimit)
  {
    for (const auto& f : this->Fresh)
    {
      if (f.first == key)
      {
        return f.second ? 1 : 0;
      }
    }
  }
  else
  {
    if (this->Local.Size() == 0)
    {
      for (const auto& f : this->Fresh)
      {
        this->Local.Insert(f.first, f.second);
      }
    }
    const int local = this->Local.Find(key);
    if (local >= 0)
    {
      return local;
    }
  }
  return -1;
}

void CellSignCache::Remember(PointKey key, bool inside)
{
  this->Fresh.emplace_back(key, inside);
  if (this->Local.Size() > 0)
  {
    this->Local.Insert(key, inside);
  }
}

} // namespace tpc
