#include "tools/topay_plan/trajectory_record.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay::plan {
namespace {

constexpr int kCoefficients = 6;  // quintic pieces, MINCO s = 3

void RequireSolved(const ArcYawTrajectory& trajectory, const char* who) {
  if (!trajectory.minco().solved()) {
    throw std::invalid_argument(std::string(who) + ": the trajectory has not been solved");
  }
}

// d^order/dt^order of sum_k c_k t^k (c: 6 coefficients, the column of one piece and dimension).
double PolynomialDerivative(const Eigen::Ref<const Eigen::VectorXd>& c, double t, int order) {
  double value = 0.0;
  for (int k = kCoefficients - 1; k >= order; --k) {
    double factor = 1.0;  // k (k - 1) ... (k - order + 1)
    for (int i = 0; i < order; ++i) factor *= k - i;
    value = value * t + factor * c(k);
  }
  return value;
}

// Value of the polynomial of `piece`, every dimension, at local time t.
Eigen::VectorXd PieceDerivative(const TrajectoryPieces& p, int piece, double t, int order) {
  const int dims = static_cast<int>(p.coefficients.cols());
  Eigen::VectorXd out(dims);
  for (int d = 0; d < dims; ++d) {
    out(d) = PolynomialDerivative(p.coefficients.block(kCoefficients * piece, d, kCoefficients, 1),
                                  t, order);
  }
  return out;
}

void CheckPieces(const TrajectoryPieces& p) {
  const Eigen::Index m = p.durations_s.size();
  if (m < 1 || p.coefficients.rows() != kCoefficients * m || p.coefficients.cols() < 3) {
    throw std::invalid_argument(
        "RebuildTrajectory: expected 6 M x D coefficients (D >= 3) for M = " + std::to_string(m) +
        " pieces, got " + std::to_string(p.coefficients.rows()) + " x " +
        std::to_string(p.coefficients.cols()));
  }
  if (!p.coefficients.allFinite() || !p.p0_W_m.allFinite() || p.panels_per_piece < 1) {
    throw std::invalid_argument("RebuildTrajectory: non-finite values or panels_per_piece < 1");
  }
}

}  // namespace

TrajectoryValidationFigures FiguresOf(const ValidationReport& report) {
  TrajectoryValidationFigures f;
  f.ok = report.ok;
  f.duration_s = report.duration_s;
  f.num_samples = report.num_samples;
  f.min_clearance_m = report.min_obstacle.clearance_m;
  f.min_clearance_part = report.min_obstacle.name;
  f.min_self_clearance_m = report.min_self.clearance_m;
  f.worst_limit_ratio = report.worst_limit.ratio;
  f.worst_limit = std::string(ToString(report.worst_limit.limit));
  if (report.worst_limit.joint >= 0) {
    f.worst_limit += " (joint " + std::to_string(report.worst_limit.joint + 1) + ")";
  }
  f.worst_limit_t_s = report.worst_limit.t_s;
  f.end_position_error_m = report.end_position_error_m;
  f.end_orientation_error_rad = report.end_orientation_error_rad;
  return f;
}

TrajectoryPieces PiecesOf(const ArcYawTrajectory& trajectory) {
  RequireSolved(trajectory, "PiecesOf");
  TrajectoryPieces pieces;
  pieces.p0_W_m = trajectory.positions().positions().col(0);
  pieces.panels_per_piece = trajectory.positions().panels_per_piece();
  pieces.durations_s = trajectory.minco().durations();
  pieces.coefficients = trajectory.minco().coefficients();
  return pieces;
}

std::vector<TrajectorySample> SampleTrajectory(const ArcYawTrajectory& trajectory,
                                               double period_s) {
  if (!(period_s >= 1e-4 && period_s <= 10.0)) {
    throw std::invalid_argument("SampleTrajectory: period " + std::to_string(period_s) +
                                " s is outside [1e-4, 10] s");
  }
  RequireSolved(trajectory, "SampleTrajectory");
  TrajectorySample point = trajectory.MakePoint();
  std::vector<TrajectorySample> samples;
  auto add = [&](double t_s) {
    trajectory.Evaluate(t_s, &point);
    TrajectorySample& sample = samples.emplace_back(point);
    sample.t_s = t_s;
    sample.jerk = Eigen::VectorXd();
  };
  const double end_s = trajectory.duration_s();
  for (long k = 0;; ++k) {
    const double t_s = static_cast<double>(k) * period_s;
    if (t_s >= end_s - 1e-9) break;
    add(t_s);
  }
  add(end_s);
  return samples;
}

ArcYawTrajectory RebuildTrajectory(const TrajectoryPieces& pieces) {
  CheckPieces(pieces);
  const int m = static_cast<int>(pieces.durations_s.size());
  const int dims = static_cast<int>(pieces.coefficients.cols());
  Eigen::MatrixXd head(dims, 3), tail(dims, 3), waypoints(dims, m - 1);
  for (int order = 0; order < 3; ++order) {
    head.col(order) = PieceDerivative(pieces, 0, 0.0, order);
    tail.col(order) = PieceDerivative(pieces, m - 1, pieces.durations_s(m - 1), order);
  }
  for (int j = 0; j + 1 < m; ++j) {
    waypoints.col(j) = PieceDerivative(pieces, j, pieces.durations_s(j), 0);
  }
  ArcYawTrajectory::Options options;
  options.integrator.panels_per_piece = pieces.panels_per_piece;
  ArcYawTrajectory trajectory(dims - 2, m, options);
  trajectory.Update(pieces.p0_W_m, head, tail, waypoints, pieces.durations_s);
  const Eigen::MatrixXd& rebuilt = trajectory.minco().coefficients();
  const double scale = 1.0 + pieces.coefficients.cwiseAbs().maxCoeff();
  const double error = (rebuilt - pieces.coefficients).cwiseAbs().maxCoeff();
  if (!(error <= 1e-6 * scale)) {
    throw std::invalid_argument(
        "RebuildTrajectory: the pieces are not a MINCO trajectory (coefficients differ by " +
        std::to_string(error) + " after re-solving; pieces not C4-continuous?)");
  }
  return trajectory;
}

}  // namespace topay::plan
