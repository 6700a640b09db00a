// Runs the built topay-plan binary end to end in a temporary folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tools/topay_plan/plan_tool.h"
#include "tools/topay_plan/trajectory_json.h"
#include "tools/viz/png_io.h"
#include "tools/viz/scene_renderer.h"
#include "tests/common/tool_test.h"

namespace topay {
namespace {

namespace fs = std::filesystem;

class TopayPlanTest : public ToolTest {
 protected:
  TopayPlanTest() : ToolTest("topay-plan") {}

};

TEST_F(TopayPlanTest, PlansABenchmarkTaskAndWritesItsOutputs) {
  // Generous bounds: ctest runs tests in parallel on loaded cores.
  const RunResult run =
      Run("--scene tables --seed 7 --range small --threads 2 --time-limit 20 "
          "--optimizer-time-limit 10 --acquisition-budget 5 --px-per-m 10 "
          "--json '" +
          Path("trajectory.json") + "' --png '" + Path("path.png") + "' --time-png '" +
          Path("time.png") + "'");
  // A plan may fail (the benchmark's success rate is below 100 %): then it exits 3 and says why.
  ASSERT_TRUE(run.exit_code == plan::kExitSuccess || run.exit_code == plan::kExitPlanFailed)
      << run.exit_code << "\n"
      << run.out << run.err;
  for (const char* part : {"search", "sampling", "optimization", "wait", "map:", "tables",
                           "small task", "omega_max 1.25"}) {
    EXPECT_NE(run.out.find(part), std::string::npos) << part << "\n" << run.out;
  }
  // Both cases: the JSON with the status, the top-down view of the 20 x 20 m room.
  const plan::TrajectoryFile file = plan::ReadTrajectoryJson(Path("trajectory.json"));
  EXPECT_EQ(file.metadata.scene_kind, "tables");
  EXPECT_EQ(file.metadata.task_range, "small");
  EXPECT_EQ(file.metadata.task_seed, 7u);
  EXPECT_EQ(viz::ReadPng(Path("path.png")).width(), viz::SceneImageWidth(205));
  if (run.exit_code == plan::kExitSuccess) {
    EXPECT_EQ(file.metadata.status, "success");
    EXPECT_NE(run.out.find("SUCCESS"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("min clearance"), std::string::npos) << run.out;
    EXPECT_GT(file.samples.size(), 1u);
    EXPECT_EQ(viz::ReadPng(Path("time.png")).width(), 1100);
  } else {
    EXPECT_NE(file.metadata.status, "success");
    EXPECT_NE(run.out.find("FAILED"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(file.metadata.failure_reason), std::string::npos) << run.out;
    EXPECT_TRUE(file.samples.empty());
    EXPECT_FALSE(fs::exists(Path("time.png")));
  }
}

TEST_F(TopayPlanTest, AnUnreachableTargetExitsWithThePlanFailureCode) {
  const RunResult run =
      Run("--scene cuboids --seed 3 --start 0 0 0 0 0 0 0 0 0 0 "
          "--target 1 0 3 0 0 0 --json '" +
          Path("failed.json") + "'");
  EXPECT_EQ(run.exit_code, plan::kExitPlanFailed) << run.out << run.err;
  EXPECT_NE(run.out.find("FAILED"), std::string::npos) << run.out;
  // Checked before any map is built: the target is above the room.
  EXPECT_NE(run.out.find("outside the room"), std::string::npos) << run.out;
  EXPECT_EQ(plan::ReadTrajectoryJson(Path("failed.json")).metadata.task_source, "command line");
}

TEST_F(TopayPlanTest, UsageErrorsExitWithCode2AndNameTheOption) {
  RunResult run = Run("--scene tables --range huge");
  EXPECT_EQ(run.exit_code, plan::kExitUsage);
  EXPECT_NE(run.err.find("huge"), std::string::npos) << run.err;
  run = Run("--scene tables --range small --time-limit abc");
  EXPECT_EQ(run.exit_code, plan::kExitUsage);
  EXPECT_NE(run.err.find("--time-limit"), std::string::npos) << run.err;
  run = Run("--scene tables --scene-file x.json --range small");
  EXPECT_EQ(run.exit_code, plan::kExitUsage);
  run = Run("--scene tables --start 0 0 nan 0 0 0 0 0 0 0 --target 1 0 0.5 0 0 0");
  EXPECT_EQ(run.exit_code, plan::kExitUsage);
  EXPECT_NE(run.err.find("--start"), std::string::npos) << run.err;
  run = Run("--scene tables --range small --base-limits fast");
  EXPECT_EQ(run.exit_code, plan::kExitUsage);
  EXPECT_NE(run.err.find("--base-limits"), std::string::npos) << run.err;
  run = Run("--scene tables --range small --base-limits config");  // the YAML sets none
  EXPECT_EQ(run.exit_code, plan::kExitUsage) << run.out << run.err;
  EXPECT_NE(run.err.find("--base-limits config"), std::string::npos) << run.err;
  run = Run("");
  EXPECT_EQ(run.exit_code, plan::kExitUsage);
  EXPECT_NE(run.err.find("--scene"), std::string::npos) << run.err;
}

TEST_F(TopayPlanTest, FileErrorsExitWithCode1AndNameTheFile) {
  const std::string missing = Path("no_such_scene.json");
  RunResult run = Run("--scene-file '" + missing + "' --range small");
  EXPECT_EQ(run.exit_code, plan::kExitError);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;
  const std::string png = Path("no_such_folder/path.png");
  run = Run("--scene tables --range small --png '" + png + "'");
  EXPECT_EQ(run.exit_code, plan::kExitError);
  EXPECT_NE(run.err.find(png), std::string::npos) << run.err;
}

// The planner YAML's fields hold unless a flag is given; the report shows the values in force.
TEST_F(TopayPlanTest, PlannerYamlFieldsHoldUnlessAFlagIsGiven) {
  std::ofstream(Path("planner.yaml")) << "planner:\n"
                                         "  time_limit_s: 7.5\n"
                                         "  sequential: true\n"
                                         "  num_threads: 1\n"
                                         "  base_limits:\n"
                                         "    v_max_mps: 0.7\n"
                                         "    a_max_mps2: 0.5\n"
                                         "    omega_max_radps: 0.6\n"
                                         "    beta_max_radps2: 0.9\n";
  // An unreachable target: the plan fails at once, the report is printed all the same.
  const std::string task = "--scene cuboids --seed 3 --start 0 0 0 0 0 0 0 0 0 0 "
                           "--target 1 0 3 0 0 0 --config '" + Path("planner.yaml") + "'";
  RunResult run = Run(task);
  ASSERT_EQ(run.exit_code, plan::kExitPlanFailed) << run.out << run.err;
  EXPECT_NE(run.out.find("sequential, 1 threads, time limit 7.5 s"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("v_max 0.7 m/s"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("the planner config's limits"), std::string::npos) << run.out;

  run = Run(task + " --time-limit 4 --threads 2 --base-limits benchmark");
  ASSERT_EQ(run.exit_code, plan::kExitPlanFailed) << run.out << run.err;
  EXPECT_NE(run.out.find("sequential, 2 threads, time limit 4.0 s"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("omega_max 1.25 rad/s"), std::string::npos) << run.out;
}

TEST_F(TopayPlanTest, NegativeSeedsAndLimitsAreUsageErrors) {
  for (const std::string args : {"--scene tables --range small --seed -1",
                                 "--scene tables --range small --seed 1.5",
                                 "--scene tables --range small --time-limit -3"}) {
    const RunResult run = Run(args);
    EXPECT_EQ(run.exit_code, plan::kExitUsage) << args << "\n" << run.err;
    EXPECT_NE(run.err.find(args.find("seed") != std::string::npos ? "--seed" : "--time-limit"),
              std::string::npos)
        << args << "\n" << run.err;
  }
}

TEST_F(TopayPlanTest, HelpListsTheExitCodes) {
  const RunResult run = Run("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("Exit codes: 0 success, 1 file or configuration error, 2 usage error, "
                         "3 plan failed"),
            std::string::npos)
      << run.out;
}

}  // namespace
}  // namespace topay
