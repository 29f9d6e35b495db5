// BoundedVector: the inline storage behaves as a vector up to its capacity,
// copies carry exactly the used part, and one element too many throws
// instead of writing past the storage.
#include "BoundedVector.h"
#include "Vector3.h"

#include <gtest/gtest.h>

#include <stdexcept>

using tpc::Vec3;

TEST(BoundedVector, HoldsAndCopiesItsElementsUpToItsCapacity)
{
  tpc::BoundedVector<Vec3, 4> v{ Vec3(1, 2, 3), Vec3(4, 5, 6) };
  EXPECT_EQ(v.size(), 2u);
  EXPECT_FALSE(v.empty());
  v.push_back(Vec3(7, 8, 9));
  EXPECT_EQ(v.back()[2], 9.0);
  EXPECT_EQ(v.front()[0], 1.0);

  tpc::BoundedVector<Vec3, 4> copy = v;
  ASSERT_EQ(copy.size(), 3u);
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(copy[i][a], v[i][a]);
    }
  }
  // A copy is independent, and assigning a shorter one shortens it.
  copy[0] = Vec3(-1, -1, -1);
  EXPECT_EQ(v[0][0], 1.0);
  copy = tpc::BoundedVector<Vec3, 4>{ Vec3(0, 0, 1) };
  EXPECT_EQ(copy.size(), 1u);
  EXPECT_EQ(copy[0][2], 1.0);

  double sum = 0.0;
  for (const Vec3& p : v)
  {
    sum += p[0];
  }
  EXPECT_EQ(sum, 12.0);
  v.clear();
  EXPECT_TRUE(v.empty());
}

TEST(BoundedVector, OneElementPastTheCapacityThrows)
{
  tpc::BoundedVector<Vec3, 2> v{ Vec3(), Vec3() };
  EXPECT_THROW(v.push_back(Vec3()), std::length_error);
  EXPECT_EQ(v.size(), 2u);
}
