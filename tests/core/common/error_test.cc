#include "core/common/error.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(ConfigErrorTest, NamesFileAndField) {
  const ConfigError error("robot.yaml", "spheres[3].radius", "must be positive");
  EXPECT_STREQ(error.what(), "robot.yaml: spheres[3].radius: must be positive");
  EXPECT_EQ(error.file(), "robot.yaml");
  EXPECT_EQ(error.field(), "spheres[3].radius");
}

TEST(ConfigErrorTest, WithoutFieldOmitsIt) {
  const ConfigError error("scene.json", "", "cannot open file");
  EXPECT_STREQ(error.what(), "scene.json: cannot open file");
}

}  // namespace
}  // namespace topay
