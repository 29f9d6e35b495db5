// The exact signs one cell's tests use: the lattice's global table where it
// knows them, else evaluated once for the cell and kept for the table.
#pragma once

#include "CsgExpression.h"
#include "LatticeSignTable.h"
#include "RootGrid.h"

#include <utility>
#include <vector>

namespace tpc
{

/// Exact signs at lattice points for one cell's tests: from the global table
/// when known, otherwise evaluated with the cell's expression and remembered
/// (the global table is only written between parallel phases).
class CellSignCache
{
public:
  CellSignCache(const LatticeSignTable& global, const RootGrid& grid,
    const CsgExpression& expression, const PrimitiveSet& primitives)
    : Global(global)
    , Grid(grid)
    , Expression(expression)
    , Primitives(primitives)
  {
  }

  bool Inside(PointKey key);
  /// Takes `inside` as the sign at `key` where it is not known yet - an
  /// exact sign another cell evaluated (FaceDecisionCache.h) - kept for the
  /// table like the ones evaluated here.
  void Learn(PointKey key, bool inside);
  /// Points evaluated here, or learned (Learn), and not yet in the global
  /// table.
  const std::vector<std::pair<PointKey, bool>>& NewSigns() const { return this->Fresh; }

private:
  /// 1 inside, 0 outside, -1 not known yet.
  int Known(PointKey key);
  void Remember(PointKey key, bool inside);

  const LatticeSignTable& Global;
  const RootGrid& Grid;
  const CsgExpression& Expression;
  const PrimitiveSet& Primitives;
  std::vector<std::pair<PointKey, bool>> Fresh;
  LatticeSignTable Local; ///< index of Fresh, once it is long
};

} // namespace tpc
