#include "tools/topay_bench/bench_options.h"

#include <gtest/gtest.h>

#include "tools/common/usage_error.h"

namespace topay::bench {
namespace {

using plan::UsageError;

std::string MessageOf(const BenchOptions& options) {
  try {
    CheckBenchOptions(options);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

BenchOptions Valid() {
  BenchOptions o;
  o.out_dir = "/tmp/x";
  o.planner_config = "planner.yaml";
  o.robot_urdf = "robot.urdf";
  o.robot_yaml = "robot.yaml";
  return o;
}

TEST(BenchOptionsTest, ParsesAMethodList) {
  EXPECT_EQ(ParseMethodList("topay,flatness", "--compare"),
            (std::vector<std::string>{"topay", "flatness"}));
  EXPECT_EQ(ParseMethodList(" jps-only , sequential", "--compare"),
            (std::vector<std::string>{"jps-only", "sequential"}));
}

TEST(BenchOptionsTest, RejectsBadMethodListsNamingTheOption) {
  for (const char* bad : {"", "topay,", "topay,,flatness", "remani", "topay,topay"}) {
    try {
      ParseMethodList(bad, "--compare");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--compare:", 0), 0u) << e.what();
    }
  }
}

TEST(BenchOptionsTest, ValidOptionsPassAndMethodsParse) {
  BenchOptions o = Valid();
  o.methods = {"flatness", "topay"};
  EXPECT_EQ(MessageOf(o), "");
  EXPECT_EQ(MethodsOf(o), (std::vector<BenchMethod>{BenchMethod::kFlatness, BenchMethod::kTopay}));
}

TEST(BenchOptionsTest, EachBadOptionIsNamed) {
  struct Case {
    void (*change)(BenchOptions*);
    const char* option;
  };
  const Case cases[] = {
      {[](BenchOptions* o) { o->scene = "forest"; }, "--scene"},
      {[](BenchOptions* o) { o->range = "huge"; }, "--range"},
      {[](BenchOptions* o) { o->num_tasks = 0; }, "--tasks"},
      {[](BenchOptions* o) { o->methods = {}; }, "--method/--compare"},
      {[](BenchOptions* o) {
         o->methods = {"topay", "topay"};
       },
       "--method/--compare"},
      {[](BenchOptions* o) { o->num_threads = -1; }, "--threads"},
      {[](BenchOptions* o) { o->time_limit_ms = 5.0; }, "--time-limit-ms"},
      {[](BenchOptions* o) { o->time_limit_ms = std::nan(""); }, "--time-limit-ms"},
      {[](BenchOptions* o) { o->base_limits = "fast"; }, "--base-limits"},
      {[](BenchOptions* o) { o->out_dir = ""; }, "--out"},
      {[](BenchOptions* o) { o->planner_config = ""; }, "--config"},
      {[](BenchOptions* o) { o->robot_urdf = ""; }, "--robot"},
  };
  for (const Case& c : cases) {
    BenchOptions o = Valid();
    c.change(&o);
    const std::string message = MessageOf(o);
    EXPECT_EQ(message.rfind(c.option, 0), 0u) << c.option << ": " << message;
  }
}

}  // namespace
}  // namespace topay::bench
