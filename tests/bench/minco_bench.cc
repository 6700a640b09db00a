// MINCO s = 3 and the arc length-yaw trajectory (issue 4, items 1-2): cost per objective
// evaluation of the trajectory part. Commands and results: docs/benchmarks.md.
//   build-minco-rel/bin/minco_bench --benchmark_repetitions=20
//       --benchmark_report_aggregates_only=true   (one line)
// Each benchmark reports mean, median, stddev, cv and p95 over the repetitions.

#include <algorithm>
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "core/trajectory/arc_yaw_position_integrator.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/jerk_energy.h"
#include "core/trajectory/minco_s3.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

constexpr int kJoints = 7;
constexpr int kDims = kJoints + 2;

double Percentile95(const std::vector<double>& values) {
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  // Nearest-rank p95.
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * sorted.size()));
  return sorted[std::max<std::size_t>(rank, 1) - 1];
}

// MINCO solve (banded LU), jerk energy and its gradient, and the adjoint solve back to
// P, T, head and tail: what every objective evaluation pays for the trajectory itself.
// Linear in M: the per-piece time (s_per_piece) should stay flat over M.
void BM_MincoSolveEnergyGradient(benchmark::State& state) {
  const int M = static_cast<int>(state.range(0));
  Rng rng(7);
  const testing::MincoInputs in = testing::RandomMincoInputs(kDims, M, &rng);
  const Eigen::VectorXd weights = JerkWeightOptions().Weights(kJoints);
  MincoS3 minco(kDims, M);
  Eigen::MatrixXd dJ_dc(6 * M, kDims);
  Eigen::VectorXd dJ_dT(M);
  MincoGradient gradient;
  gradient.Resize(kDims, M);
  for (auto _ : state) {
    minco.Solve(in.head, in.tail, in.waypoints, in.durations);
    double energy = JerkEnergy(minco.coefficients(), minco.durations(), weights);
    dJ_dc.setZero();
    dJ_dT.setZero();
    AddJerkEnergyGradient(minco.coefficients(), minco.durations(), weights, dJ_dc, dJ_dT);
    minco.PropagateGradient(dJ_dc, dJ_dT, &gradient);
    benchmark::DoNotOptimize(energy);
    benchmark::DoNotOptimize(gradient.durations.data());
  }
  // Seconds per piece (shown with an SI prefix, e.g. "450n" = 450 ns).
  state.counters["s_per_piece"] = benchmark::Counter(
      static_cast<double>(M), benchmark::Counter::kIsIterationInvariantRate |
                                  benchmark::Counter::kInvert);
}

// Simpson x, y samples (M = 10 pieces, K = 12 panels: 121 samples, 250 integrand points) and
// the reverse accumulation of a gradient on every sample back to c and T.
void BM_SimpsonPositionsAndGradient(benchmark::State& state) {
  const int M = 10;
  ArcYawPositionIntegrator::Options options;
  options.panels_per_piece = static_cast<int>(state.range(0));
  Rng rng(8);
  const testing::MincoInputs in = testing::RandomMincoInputs(kDims, M, &rng);
  MincoS3 minco(kDims, M);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  ArcYawPositionIntegrator integrator(M, options);
  const Eigen::Matrix2Xd dC_dp =
      testing::RandomMatrix(2, integrator.num_samples(), -1.0, 1.0, &rng);
  Eigen::MatrixXd dC_dc(6 * M, kDims);
  Eigen::VectorXd dC_dT(M);
  for (auto _ : state) {
    integrator.Integrate(Eigen::Vector2d(0.5, -0.5), minco.coefficients(), minco.durations());
    dC_dc.setZero();
    dC_dT.setZero();
    const Eigen::Vector2d dC_dp0 = integrator.AddGradient(dC_dp, dC_dc, dC_dT);
    benchmark::DoNotOptimize(dC_dp0.data());
    benchmark::DoNotOptimize(dC_dc.data());
  }
}

// Everything of items 1-2 in one objective evaluation, M = 10, N = 7, K = 12: MINCO solve,
// Simpson x, y, jerk energy, gradient of a cost on every x, y sample and of the energy carried
// back through the Simpson chain and MINCO to P, T, head, tail and p0.
void BM_ArcYawTrajectoryEvaluation(benchmark::State& state) {
  const int M = 10;
  Rng rng(9);
  const testing::MincoInputs in = testing::RandomMincoInputs(kDims, M, &rng);
  const Eigen::VectorXd weights = JerkWeightOptions().Weights(kJoints);
  ArcYawTrajectory trajectory(kJoints, M, ArcYawTrajectory::Options{});
  const int samples = M * ArcYawPositionIntegrator::Options{}.panels_per_piece + 1;
  const Eigen::Matrix2Xd dC_dp = testing::RandomMatrix(2, samples, -1.0, 1.0, &rng);
  Eigen::MatrixXd dC_dc(6 * M, kDims);
  Eigen::VectorXd dC_dT(M);
  MincoGradient gradient;
  gradient.Resize(kDims, M);
  for (auto _ : state) {
    trajectory.Update(Eigen::Vector2d(0.5, -0.5), in.head, in.tail, in.waypoints, in.durations);
    const double energy =
        JerkEnergy(trajectory.minco().coefficients(), trajectory.minco().durations(), weights);
    dC_dc.setZero();
    dC_dT.setZero();
    AddJerkEnergyGradient(trajectory.minco().coefficients(), trajectory.minco().durations(),
                          weights, dC_dc, dC_dT);
    const Eigen::Vector2d dC_dp0 = trajectory.PropagateGradient(dC_dp, dC_dc, dC_dT, &gradient);
    benchmark::DoNotOptimize(energy);
    benchmark::DoNotOptimize(dC_dp0.data());
    benchmark::DoNotOptimize(gradient.waypoints.data());
  }
}

BENCHMARK(BM_MincoSolveEnergyGradient)
    ->Arg(5)->Arg(10)->Arg(20)->Arg(40)->ArgName("M")
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("p95", Percentile95);
BENCHMARK(BM_SimpsonPositionsAndGradient)
    ->Arg(12)->ArgName("K")
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("p95", Percentile95);
BENCHMARK(BM_ArcYawTrajectoryEvaluation)
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("p95", Percentile95);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
