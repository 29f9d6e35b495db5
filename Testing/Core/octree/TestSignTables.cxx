// The exact signs at lattice points: the lattice's global table
// (LatticeSignTable.h) and one cell's cache over it (CellSignCache.h). Every
// corner of the octree is read from them; a lost or wrong entry would give
// two cells different signs at one corner.
#include "CellSignCache.h"
#include "LatticeSignTable.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

using tpc::PointKey;

TEST(LatticeSignTable, AgreesWithAMapThroughGrowth)
{
  tpc::LatticeSignTable table;
  std::unordered_map<PointKey, bool, tpc::LatticeKeyHash> reference;
  std::mt19937_64 random(7);
  EXPECT_EQ(table.Find(0), -1); // empty
  for (int i = 0; i < 20000; ++i)
  {
    // Keys with many bits alike (neighbouring lattice points), and key 0.
    const PointKey key = i == 0 ? 0 : tpc::MakePointKey(random() % 64, random() % 64, random() % 4096);
    const bool inside = (random() & 1) != 0;
    table.Insert(key, inside);
    reference.emplace(key, inside); // the first sign of a key stays, as in the table
  }
  EXPECT_EQ(table.Size(), reference.size());
  for (const auto& entry : reference)
  {
    ASSERT_EQ(table.Find(entry.first), entry.second ? 1 : 0) << static_cast<std::uint64_t>(entry.first);
  }
  EXPECT_EQ(table.Find(tpc::MakePointKey(100, 100, 100)), -1);
  // Inserting a known key again changes nothing.
  const auto known = *reference.begin();
  table.Insert(known.first, !known.second);
  EXPECT_EQ(table.Find(known.first), known.second ? 1 : 0);
  EXPECT_EQ(table.Size(), reference.size());
}

namespace
{
/// A sphere of radius 0.3 at the centre of a unit root cell, on a lattice
/// of 2^10 spacings.
struct SphereLattice
{
  tpctest::SceneBuilder Builder;
  tpc::RootGrid Grid = tpctest::SingleRoot({ 0, 0, 0 }, 1.0, 10);
  tpc::LatticeSignTable Global;

  SphereLattice() { this->Builder.Finish(this->Builder.Sphere({ 0.5, 0.5, 0.5 }, 0.3)); }
  bool Exact(PointKey key) const
  {
    return this->Builder.Scene.Expression->IsInside(this->Grid.Point(key), this->Builder.Scene.Primitives);
  }
  tpc::CellSignCache Cache() const
  {
    return tpc::CellSignCache(this->Global, this->Grid, *this->Builder.Scene.Expression, this->Builder.Scene.Primitives);
  }
};
} // namespace

TEST(CellSignCache, KnownSignsComeFromTheTableFreshOnesAreKeptOnce)
{
  SphereLattice s;
  const PointKey centre = tpc::MakePointKey(512, 512, 512), corner = tpc::MakePointKey(0, 0, 0);
  // A wrong entry in the global table is what the cache must return: it
  // asks the table first and never evaluates a known point again.
  s.Global.Insert(centre, false);
  tpc::CellSignCache cache = s.Cache();
  EXPECT_FALSE(cache.Inside(centre));
  EXPECT_TRUE(cache.NewSigns().empty());
  EXPECT_FALSE(cache.Inside(corner));
  EXPECT_TRUE(cache.Inside(tpc::MakePointKey(512, 512, 600)));
  ASSERT_EQ(cache.NewSigns().size(), 2u);
  EXPECT_TRUE(cache.Inside(tpc::MakePointKey(512, 512, 600)));
  EXPECT_FALSE(cache.Inside(corner));
  EXPECT_EQ(cache.NewSigns().size(), 2u); // asked twice, evaluated once
}

TEST(CellSignCache, ManyFreshSignsStayExactAndDistinct)
{
  // Past a few dozen fresh points the cache indexes them in a hash table
  // (a face refined along a long sliver evaluates thousands).
  SphereLattice s;
  for (std::uint32_t i = 0; i < 1024; i += 16)
  {
    s.Global.Insert(tpc::MakePointKey(i, 512, 512), s.Exact(tpc::MakePointKey(i, 512, 512)));
  }
  tpc::CellSignCache cache = s.Cache();
  std::mt19937 random(3);
  std::unordered_map<PointKey, bool, tpc::LatticeKeyHash> asked;
  for (int k = 0; k < 5000; ++k)
  {
    const PointKey key = tpc::MakePointKey(random() % 1025, 512, random() % 1025);
    const bool inside = cache.Inside(key);
    ASSERT_EQ(inside, s.Exact(key)) << static_cast<std::uint64_t>(key);
    asked.emplace(key, inside);
  }
  std::unordered_map<PointKey, bool, tpc::LatticeKeyHash> fresh;
  for (const auto& sign : cache.NewSigns())
  {
    EXPECT_TRUE(fresh.emplace(sign.first, sign.second).second) << "evaluated twice: " << static_cast<std::uint64_t>(sign.first);
    EXPECT_EQ(s.Global.Find(sign.first), -1) << "known to the table: " << static_cast<std::uint64_t>(sign.first);
    EXPECT_EQ(sign.second, asked.at(sign.first));
  }
  std::size_t known = 0;
  for (const auto& a : asked)
  {
    known += s.Global.Find(a.first) >= 0 ? 1 : 0;
  }
  EXPECT_EQ(fresh.size() + known, asked.size());
  EXPECT_GT(fresh.size(), 64u);
}
