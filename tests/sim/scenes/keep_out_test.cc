#include "sim/scenes/keep_out.h"
#include "tests/common/make_box.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(KeepOutTest, CylinderAndBoxRegions) {
  KeepOutRegions regions;
  EXPECT_TRUE(regions.Admits(MakeBox({0, 0, 0.5}, {1, 1, 1})));  // nothing kept out
  regions.cylinders.push_back({Eigen::Vector2d(0.0, 0.0), 1.0, 0.0, 1.6});
  EXPECT_FALSE(regions.Admits(MakeBox({1.2, 0.0, 0.5}, {0.5, 0.5, 1.0})));  // edge at 0.95
  EXPECT_TRUE(regions.Admits(MakeBox({1.3, 0.0, 0.5}, {0.5, 0.5, 1.0})));   // edge at 1.05
  // A box over the cylinder's top does not enter it.
  EXPECT_TRUE(regions.Admits(MakeBox({0.0, 0.0, 1.8}, {0.3, 0.3, 0.3})));
  regions.boxes.push_back(MakeBox({5.0, 5.0, 0.5}, {2.0, 2.0, 1.0}, 0.3));
  EXPECT_FALSE(regions.Admits(MakeBox({5.9, 5.0, 0.2}, {0.5, 0.5, 0.4})));
  EXPECT_TRUE(regions.Admits(MakeBox({7.0, 7.0, 0.2}, {0.5, 0.5, 0.4})));
}

}  // namespace
}  // namespace topay
