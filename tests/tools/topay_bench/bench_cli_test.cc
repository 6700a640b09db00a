#include "tools/topay_bench/bench_cli.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/common/usage_error.h"

namespace topay::bench {
namespace {

// Parses `args` (without the program name) as topay-bench would.
BenchCommandLine Parse(std::vector<std::string> args) {
  CLI::App app;
  BenchCommandLine line;
  AddBenchFlags("/cfg", &app, &line);
  std::vector<const char*> argv = {"topay-bench"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  FinishBenchCommandLine(&line);
  return line;
}

TEST(BenchCliTest, DefaultsAreOpenTasksAndTheConfigFolder) {
  const BenchOptions o = Parse({"--out", "/tmp/x"}).options;
  EXPECT_FALSE(o.tight);
  EXPECT_EQ(o.scene, "cuboids");
  EXPECT_EQ(o.range, "medium");
  EXPECT_EQ(o.methods, std::vector<std::string>{"topay"});
  EXPECT_EQ(o.planner_config, "/cfg/planner/topay.yaml");
  EXPECT_EQ(o.robot_urdf, "/cfg/robot/topay_mm.urdf");
  EXPECT_EQ(o.out_dir, "/tmp/x");
  EXPECT_TRUE(o.use_hint);
}

TEST(BenchCliTest, TightAndTheOtherTaskFlags) {
  const BenchOptions o = Parse({"--scene", "tables", "--range", "small", "--tight", "--tasks",
                                "5", "--seed", "9", "--compare", "topay,flatness", "--no-hint",
                                "--out", "/tmp/y"})
                             .options;
  EXPECT_TRUE(o.tight);
  EXPECT_EQ(o.scene, "tables");
  EXPECT_EQ(o.range, "small");
  EXPECT_EQ(o.num_tasks, 5);
  EXPECT_EQ(o.seed, 9u);
  EXPECT_EQ(o.methods, (std::vector<std::string>{"topay", "flatness"}));
  EXPECT_FALSE(o.use_hint);
}

TEST(BenchCliTest, MistakesAreUsageOrParseErrors) {
  EXPECT_THROW(Parse({"--method", "topay,flatness", "--out", "/tmp/z"}), plan::UsageError);
  EXPECT_THROW(Parse({"--tight=maybe", "--out", "/tmp/z"}), CLI::ParseError);
  EXPECT_THROW(Parse({"--tight"}), CLI::ParseError);  // --out is required
  EXPECT_THROW(Parse({"--seed", "-1", "--out", "/tmp/z"}), CLI::ParseError);
}

}  // namespace
}  // namespace topay::bench
