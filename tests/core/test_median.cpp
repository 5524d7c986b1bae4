#include "core/median.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace dynanav {
namespace {

TEST(Median, IsTheMiddleElementAndTheUpperOneOfAnEvenCount) {
  std::vector<double> odd{5.0, -1.0, 3.0, 9.0, 0.5};
  EXPECT_EQ(medianInPlace(odd), 3.0);
  std::vector<int> even{4, 1, 3, 2};
  EXPECT_EQ(medianInPlace(even), 3);  // not 2.5: the median is one of the values
  std::vector<float> one{7.f};
  EXPECT_EQ(medianInPlace(one), 7.f);
}

TEST(Median, OfACopyLeavesTheValuesInTheirOrder) {
  const std::vector<double> values{3.0, 1.0, 2.0, 10.0, -4.0};
  EXPECT_EQ(medianOf(values), 2.0);
  EXPECT_EQ(values, (std::vector<double>{3.0, 1.0, 2.0, 10.0, -4.0}));
}

}  // namespace
}  // namespace dynanav
