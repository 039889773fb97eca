#include <gtest/gtest.h>

#include "fixed_point.h"

using namespace sc;

TEST(FixedPoint, ChooseMatchesDefinition) {
  for (uint64_t k = 0; k < 200; ++k) {
    EXPECT_EQ(choose2(k), u128(k * (k ? k - 1 : 0) / 2));
    EXPECT_EQ(choose3(k), u128(k < 3 ? 0 : k * (k - 1) * (k - 2) / 6));
  }
  const uint64_t big = 4294967295ull;
  EXPECT_EQ(choose3(big), u128(big) * (big - 1) * (big - 2) / 6);
}
