// The NMPC tracker's solve time (issue 19): closed loops (ideal unicycle + integrator plant,
// 20 ms command latency, 50 Hz) along synthetic references at the robot's limits, from small
// offsets; every solve's wall time (NmpcSummary::solve_ms, one thread) is collected and the
// median / p95 / p99 / max reported per scenario and over all. Commands and results:
// docs/benchmarks.md, "NMPC tracker (issue 19)".
//   build-nmpc/bin/nmpc_bench --benchmark_counters_tabular=true

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "core/common/sample_statistics.h"
#include "core/control/nmpc_solver.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::ReferenceInputs;
using testing::StateAt;
using testing::SyntheticReference;
using testing::Trapezoid;

struct Scenario {
  std::string name;
  double duration_s;
  testing::InputProfile profile;
};

// References at the limits (v_max 1.0, a_max 0.8, omega_max 0.9, beta_max 1.0, coupled
// |v| + |omega| / 0.9 <= 1; joints 2.35 rad/s, 6.28 rad/s^2), each with its feed-forward.
std::vector<Scenario> Scenarios() {
  return {
      {"straight", 8.0,
       [](double t) {
         ReferenceInputs in;
         in.v_mps = Trapezoid(t, 0.0, 8.0, 0.95, 0.75);
         return in;
       }},
      {"s_curve", 10.0,
       [](double t) {
         ReferenceInputs in;
         const double ramp = std::min({1.0, t / 1.0, (10.0 - t) / 1.0});
         in.v_mps = 0.55 * ramp;
         in.omega_radps = 0.38 * ramp * std::sin(0.9 * t);
         return in;
       }},
      {"turn_in_place", 6.0,
       [](double t) {
         ReferenceInputs in;
         in.omega_radps = Trapezoid(t, 0.0, 3.0, 0.85, 0.9) - Trapezoid(t, 3.0, 6.0, 0.85, 0.9);
         return in;
       }},
      {"arm_sweep", 6.0,
       [](double t) {
         ReferenceInputs in;
         for (int j = 0; j < kJoints; ++j) {
           in.qd_radps(j) = 2.2 * std::sin(2.5 * t + j) * std::min(1.0, t);
         }
         return in;
       }},
      {"whole_body", 10.0,
       [](double t) {
         ReferenceInputs in;
         const double ramp = std::min({1.0, t / 1.2, (10.0 - t) / 1.2});
         in.v_mps = 0.5 * ramp;
         in.omega_radps = 0.4 * ramp * std::sin(0.7 * t);
         for (int j = 0; j < kJoints; ++j) in.qd_radps(j) = 1.5 * ramp * std::sin(1.3 * t + j);
         return in;
       }},
      {"sharp_corners", 10.0,
       [](double t) {
         ReferenceInputs in;
         in.v_mps = Trapezoid(t, 0.0, 10.0, 0.5, 0.6);
         const double phase = std::fmod(t, 2.5);
         if (t > 1.0 && phase >= 1.0 && phase < 1.02) in.omega_radps = 0.5 * std::numbers::pi / 0.02;
         return in;
       }},
  };
}

// Wall-clock solve times (the budget's clock) into the return value, thread CPU times into
// *cpu_ms (what the solve costs without the scheduler's share of a busy machine).
std::vector<double> RunScenario(const Scenario& scenario, int repeats, int* fallbacks,
                                std::vector<double>* cpu_ms) {
  std::vector<double> solve_ms;
  Rng rng(19);
  for (int r = 0; r < repeats; ++r) {
    NmpcSolver solver(NmpcOptions(), testing::TopayLimits());
    const SyntheticReference reference(scenario.profile, scenario.duration_s, StateAt(0, 0, 0, 0));
    // Start a few cm / cRad off.
    const WholeBodyState start = StateAt(rng.Uniform(-0.05, 0.05), rng.Uniform(-0.05, 0.05),
                                         rng.Uniform(-0.05, 0.05), rng.Uniform(-0.05, 0.05));
    const testing::ClosedLoopResult result =
        testing::RunClosedLoop(&solver, reference, start, scenario.duration_s + 1.0, &solve_ms,
                               cpu_ms);
    *fallbacks += result.fallbacks;
  }
  return solve_ms;
}

void SetCounters(benchmark::State& state, const std::vector<double>& solve_ms,
                 const std::vector<double>& cpu_ms, int fallbacks) {
  state.counters["solves"] = static_cast<double>(solve_ms.size());
  state.counters["median_ms"] = Median(solve_ms);
  state.counters["p95_ms"] = NearestRankQuantile(solve_ms, 0.95);
  state.counters["p99_ms"] = NearestRankQuantile(solve_ms, 0.99);
  state.counters["max_ms"] = NearestRankQuantile(solve_ms, 1.0);
  state.counters["fallbacks"] = fallbacks;
  state.counters["cpu_median_ms"] = Median(cpu_ms);
  state.counters["cpu_p99_ms"] = NearestRankQuantile(cpu_ms, 0.99);
}

void BM_NmpcScenario(benchmark::State& state) {
  const Scenario scenario = Scenarios()[state.range(0)];
  std::vector<double> solve_ms;
  std::vector<double> cpu_ms;
  int fallbacks = 0;
  for (auto _ : state) solve_ms = RunScenario(scenario, 3, &fallbacks, &cpu_ms);
  state.SetLabel(scenario.name);
  SetCounters(state, solve_ms, cpu_ms, fallbacks);
}
BENCHMARK(BM_NmpcScenario)->DenseRange(0, 5)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_NmpcAll(benchmark::State& state) {
  std::vector<double> all;
  std::vector<double> cpu_ms;
  int fallbacks = 0;
  for (auto _ : state) {
    all.clear();
    for (const Scenario& scenario : Scenarios()) {
      const std::vector<double> ms = RunScenario(scenario, 3, &fallbacks, &cpu_ms);
      all.insert(all.end(), ms.begin(), ms.end());
    }
  }
  state.SetLabel("all scenarios");
  SetCounters(state, all, cpu_ms, fallbacks);
}
BENCHMARK(BM_NmpcAll)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
