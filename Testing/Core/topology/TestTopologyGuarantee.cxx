// TopologyGuaranteed is the conjunction of its conditions (TopologyGuarantee.h):
// each one alone withholds it.
#include "TopologyGuarantee.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace
{
tpc::GuaranteeConditions AllHold()
{
  tpc::GuaranteeConditions c;
  c.AssumptionsMet = c.EveryCellResolved = c.LoopsConsistent = c.Embedded = c.WithinTolerance = c.WholeSurface =
    c.ClosedOrientedManifold = c.Outward = true;
  return c;
}
} // namespace

TEST(TopologyGuarantee, HoldsOnlyWhenEveryConditionHolds)
{
  EXPECT_TRUE(tpc::TopologyGuaranteed(AllHold()));
  EXPECT_FALSE(tpc::TopologyGuaranteed(tpc::GuaranteeConditions{})) << "nothing known, nothing guaranteed";
  const std::vector<std::pair<const char*, bool tpc::GuaranteeConditions::*>> conditions{
    { "AssumptionsMet", &tpc::GuaranteeConditions::AssumptionsMet },
    { "EveryCellResolved", &tpc::GuaranteeConditions::EveryCellResolved },
    { "LoopsConsistent", &tpc::GuaranteeConditions::LoopsConsistent },
    { "Embedded", &tpc::GuaranteeConditions::Embedded },
    { "WithinTolerance", &tpc::GuaranteeConditions::WithinTolerance },
    { "WholeSurface", &tpc::GuaranteeConditions::WholeSurface },
    { "ClosedOrientedManifold", &tpc::GuaranteeConditions::ClosedOrientedManifold },
    { "Outward", &tpc::GuaranteeConditions::Outward },
  };
  // (Eight conditions: the struct holds no other - a ninth added without a
  // line here fails the size check.)
  EXPECT_EQ(sizeof(tpc::GuaranteeConditions), conditions.size() * sizeof(bool));
  for (const auto& [name, condition] : conditions)
  {
    tpc::GuaranteeConditions c = AllHold();
    c.*condition = false;
    EXPECT_FALSE(tpc::TopologyGuaranteed(c)) << name << " alone failing must withhold the guarantee";
  }
}
