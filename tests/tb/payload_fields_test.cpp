// Every variant's payload field list (hls/fields.h) against its RTL: the
// own inputs in the order rtl/<core>.sv declares them, each as wide as the
// RTL port at the variant's parameters, and the shared inputs as the port
// contract has them. The RTL side is read by scripts/rtl_ports.py (the
// declarations scripts/port_pages.py documents).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "run_hwinterp.h"
#include "tb/base/json.h"
#include "tb/lockstep/bench.h"
#include "tb/lockstep/registry.h"

namespace hwinterp::tb::testing {
namespace {

using hwinterp::testing::scratch_dir;
using hwinterp::testing::slurp;

// The RTL's ports of every variant, as scripts/rtl_ports.py reads them.
Json rtl_ports() {
  const std::string out = scratch_dir("rtl_ports") + "/ports.json";
  const std::string cmd = std::string("'") + HWINTERP_PYTHON +
                          "' '" HWINTERP_SOURCE_DIR "/scripts/rtl_ports.py' '" HWINTERP_VARIANTS_TXT
                          "' > '" +
                          out + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return Json::parse(slurp(out));
}

TEST(PayloadFields, MatchTheRtlPorts) {
  const Json rtl = rtl_ports();
  int variants = 0;
  for (const CoreEntry& core : all_cores()) {
    for (const VariantEntry& v : core.variants) {
      SCOPED_TRACE(v.spec.variant);
      ASSERT_TRUE(rtl.contains(v.spec.variant));
      ++variants;
      // The shared inputs, as the contract has them (name -> bits).
      std::set<std::string> shared;
      std::vector<std::pair<std::string, int>> own_rtl;
      const std::vector<PortSpec> all = input_ports(v.spec);
      for (const PortSpec& p : all) shared.insert(p.name);
      for (const PortSpec& p : v.spec.own_ports) shared.erase(p.name);
      for (const Json& p : rtl[v.spec.variant]) {
        const std::string name = p["name"];
        if (p["dir"] != "input" || name == "clk_i") continue;
        if (shared.count(name)) {
          bool found = false;
          for (const PortSpec& s : all)
            if (s.name == name) {
              EXPECT_EQ(s.count * s.width, p["bits"].get<int>()) << name;
              found = true;
            }
          EXPECT_TRUE(found) << name;
          shared.erase(name);
        } else {
          own_rtl.emplace_back(name, p["bits"].get<int>());
        }
      }
      EXPECT_TRUE(shared.empty()) << "contract inputs the RTL lacks: " << *shared.begin();
      // The own inputs: the field list, in the RTL's order, as wide.
      ASSERT_EQ(own_rtl.size(), v.spec.own_ports.size());
      for (size_t i = 0; i < own_rtl.size(); ++i) {
        const PortSpec& f = v.spec.own_ports[i];
        EXPECT_EQ(f.name, own_rtl[i].first) << "field " << i;
        EXPECT_EQ(f.count * f.width, own_rtl[i].second) << f.name;
      }
    }
  }
  EXPECT_GT(variants, 0);
}

// The field list is what the pins carry: a payload's flat values come back
// from its fields element by element, signed fields as numbers.
TEST(PayloadFields, SignedFieldsReadBackAsNumbers) {
  const PortSpec delta{"cmd_delta_i", 2, 12, true}, ops{"cmd_ops_i", 1, 14, false};
  EXPECT_EQ(delta.value(0xFFF), -1);
  EXPECT_EQ(delta.value(0x800), -2048);
  EXPECT_EQ(delta.value(0x7FF), 2047);
  EXPECT_EQ(ops.value(0x3FFF), 0x3FFF);
  EXPECT_TRUE(delta.fits(-2048));
  EXPECT_FALSE(delta.fits(2048));
  EXPECT_FALSE(ops.fits(-1));
  EXPECT_EQ(delta.range_text(), "-2048..2047");
}

}  // namespace
}  // namespace hwinterp::tb::testing
