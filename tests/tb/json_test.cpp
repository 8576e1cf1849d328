// The report writer: insertion order, bytes that are not UTF-8, non-finite
// numbers, and write errors that must not pass silently.
#include "tb/base/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace hwinterp {
namespace {

TEST(Json, KeepsInsertionOrder) {
  Json j;
  j["zeta"] = 1;
  j["alpha"] = 2;
  EXPECT_LT(dump_json(j).find("zeta"), dump_json(j).find("alpha"));
}

// A job-file case name with a byte >= 0x80 that is not UTF-8 still gives a
// valid document.
TEST(Json, InvalidUtf8IsReplacedNotFatal) {
  Json j;
  j["case"] = std::string("caf\xe9");
  const std::string text = dump_json(j);
  EXPECT_EQ(Json::parse(text)["case"], "caf\xef\xbf\xbd");
}

TEST(Json, NonFiniteIsNull) {
  Json j;
  j["x"] = std::nan("");
  EXPECT_TRUE(Json::parse(dump_json(j))["x"].is_null());
}

TEST(Json, WriteErrorsThrowNamingThePath) {
  EXPECT_THROW(write_json_file("/no/such/dir/r.json", Json::object()), std::runtime_error);
  try {
    write_json_file("/dev/full", Json::object());
    FAIL() << "a write to /dev/full passed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos);
  }
}

}  // namespace
}  // namespace hwinterp
