#pragma once

#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/planner_config.h"

namespace topay::testing {

/// A planner YAML text and the dotted field its ConfigError must name.
struct BadConfigCase {
  const char* yaml;
  const char* field;
};

/// Expects ParsePlannerOptions to throw a ConfigError naming "bad.yaml" and the case's field.
inline void ExpectConfigErrorNamesTheField(const BadConfigCase& c) {
  try {
    ParsePlannerOptions(c.yaml, "bad.yaml");
    ADD_FAILURE() << "no error for: " << c.yaml;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "bad.yaml") << c.yaml;
    EXPECT_EQ(e.field(), c.field) << c.yaml << " -> " << e.what();
  }
}

}  // namespace topay::testing
