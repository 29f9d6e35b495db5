#include "CellRepair.h"

#include <algorithm>
#include <tuple>

namespace tpc
{
namespace
{
auto Order(int level, const LatticeIndex ijk[3])
{
  return std::make_tuple(level, ijk[0], ijk[1], ijk[2]);
}
bool Before(const CellToSplit& a, const CellToSplit& b)
{
  return Order(a.Level, a.Ijk) < Order(b.Level, b.Ijk);
}
} // namespace

void CellsToSplit::Add(const CellToSplit& cell)
{
  const auto at = std::lower_bound(this->Cells.begin(), this->Cells.end(), cell, Before);
  if (at == this->Cells.end() || Before(cell, *at))
  {
    this->Cells.insert(at, cell);
  }
}

const CellToSplit* CellsToSplit::Find(int level, const LatticeIndex ijk[3]) const
{
  CellToSplit key;
  key.Level = static_cast<std::uint8_t>(level);
  std::copy(ijk, ijk + 3, key.Ijk);
  const auto at = std::lower_bound(this->Cells.begin(), this->Cells.end(), key, Before);
  return at != this->Cells.end() && !Before(key, *at) ? &*at : nullptr;
}

} // namespace tpc
