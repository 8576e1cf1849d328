#include "json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hwinterp {
namespace {

TEST(Json, KeepsInsertionOrderAndEscapes) {
  Json j = Json::object();
  j.set("b", 1);
  j.set("a", "x\"y\n");
  j.set("v", Json::array_of(std::vector<int64_t>{1, -2}));
  EXPECT_EQ(j.dump(0), "{\"b\":1,\"a\":\"x\\\"y\\n\",\"v\":[1, -2]}");
}

TEST(Json, RealsRoundTripAndNonFiniteIsNull) {
  Json j = Json::array();
  j.push(0.1);
  j.push(3.9785e-5);
  j.push(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(j.dump(0), "[0.1, 3.9785e-05, null]");
}

}  // namespace
}  // namespace hwinterp
