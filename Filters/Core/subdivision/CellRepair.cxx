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

std::vector<double> CellsToSplit::Serialize() const
{
  std::vector<double> out;
  out.reserve(5 * this->Cells.size());
  for (const CellToSplit& c : this->Cells)
  {
    out.insert(out.end(), { static_cast<double>(c.Level), static_cast<double>(c.Ijk[0]),
                            static_cast<double>(c.Ijk[1]), static_cast<double>(c.Ijk[2]),
                            static_cast<double>(static_cast<int>(c.Reason)) });
  }
  return out;
}

void CellsToSplit::AddSerialized(const std::vector<double>& cells)
{
  for (std::size_t i = 0; i + 5 <= cells.size(); i += 5)
  {
    CellToSplit c;
    c.Level = static_cast<std::uint8_t>(cells[i]);
    for (int a = 0; a < 3; ++a)
    {
      c.Ijk[a] = static_cast<LatticeIndex>(cells[i + 1 + static_cast<std::size_t>(a)]);
    }
    c.Reason = static_cast<SplitReason>(static_cast<int>(cells[i + 4]));
    this->Add(c);
  }
}

} // namespace tpc
