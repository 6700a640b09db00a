#include "procs/msgs/trajectory_from_message.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace topay::msgs {
namespace {

constexpr int kCoefficients = 6;  // quintic pieces

/// d^order/dt^order of piece `piece` at local time t_s (one value per dimension).
Eigen::VectorXd PieceDerivative(const Eigen::MatrixXd& c, int piece, double t_s, int order) {
  Eigen::VectorXd value = Eigen::VectorXd::Zero(c.cols());
  double power = 1.0;  // t^(k - order)
  for (int k = order; k < kCoefficients; ++k, power *= t_s) {
    double factor = 1.0;  // k! / (k - order)!
    for (int i = 0; i < order; ++i) factor *= k - i;
    value += factor * power * c.row(kCoefficients * piece + k).transpose();
  }
  return value;
}

std::string Named(const PolyTrajectory& poly, const std::string& reason) {
  return "trajectory " + std::to_string(poly.trajectory_id) + " (goal " + std::to_string(poly.goal_id) + "): " + reason;
}

template <class... Parts>
std::string Text(const Parts&... parts) {
  std::ostringstream text;
  text.precision(6);
  (text << ... << parts);
  return text.str();
}

}  // namespace

MincoBoundary BoundaryOf(const PolyTrajectory& poly) {
  const int m = poly.num_pieces();
  const int dims = static_cast<int>(poly.coefficients.cols());
  MincoBoundary b;
  b.head.resize(dims, 3);
  b.tail.resize(dims, 3);
  b.waypoints.resize(dims, m - 1);
  b.durations_s = poly.durations_s;
  for (int order = 0; order < 3; ++order) {
    b.head.col(order) = PieceDerivative(poly.coefficients, 0, 0.0, order);
    b.tail.col(order) = PieceDerivative(poly.coefficients, m - 1, poly.durations_s(m - 1), order);
  }
  for (int i = 0; i + 1 < m; ++i) b.waypoints.col(i) = PieceDerivative(poly.coefficients, i, poly.durations_s(i), 0);
  return b;
}

double RelativeCoefficientError(const PolyTrajectory& poly, const Eigen::MatrixXd& coefficients) {
  // A re-solve that overflowed to NaN somewhere compares as no difference (every comparison
  // with NaN is false; found by tests/fuzz/trajectory_message_fuzz.cc: coefficients of 3e304
  // re-solved to NaN in one joint, were accepted, and sampled to NaN joints).
  if (!coefficients.allFinite()) return std::numeric_limits<double>::infinity();
  double difference = 0.0, size = 1.0;
  for (int j = 0; j < poly.num_pieces(); ++j) {
    double power = 1.0;  // T_j^k
    for (int k = 0; k < kCoefficients; ++k, power *= poly.durations_s(j)) {
      const int row = kCoefficients * j + k;
      difference = std::max(difference, (coefficients.row(row) - poly.coefficients.row(row)).cwiseAbs().maxCoeff() * power);
      size = std::max(size, poly.coefficients.row(row).cwiseAbs().maxCoeff() * power);
    }
  }
  // A trajectory whose weighted coefficients come near the largest double cannot be evaluated
  // (the sum of six terms and the derivatives' factors up to 60 overflow to inf): as far from a
  // MINCO solution as can be (found by tests/fuzz/trajectory_message_fuzz.cc: a 3.7e307
  // coefficient gave 0 here, was accepted, and sampled to non-finite joints).
  constexpr double kLargestEvaluable = std::numeric_limits<double>::max() / 1024;
  if (!(size <= kLargestEvaluable) || !std::isfinite(difference)) return std::numeric_limits<double>::infinity();
  return difference / size;
}

std::optional<ArcYawTrajectory> ToArcYaw(const PolyTrajectory& poly, const TrajectoryRebuildOptions& options,
                                         std::string* error) {
  const int m = poly.num_pieces();
  if (m < 1 || poly.num_joints() < 0 || poly.coefficients.rows() != kCoefficients * m) {
    *error = Named(poly, Text(m, " pieces but ", poly.coefficients.rows(), " coefficient rows"));
    return std::nullopt;
  }
  for (Eigen::Index j = 0; j < poly.durations_s.size(); ++j) {
    const double t = poly.durations_s(j);
    if (!(t >= options.min_piece_duration_s && t <= options.max_piece_duration_s)) {
      *error = Named(poly, Text("piece ", j, " lasts ", t, " s, not in [", options.min_piece_duration_s, ", ",
                                options.max_piece_duration_s, "] s"));
      return std::nullopt;
    }
  }
  const double yaw_at_0 = poly.coefficients(0, 1);
  if (!(std::abs(poly.yaw0_rad - yaw_at_0) <= options.yaw0_tolerance_rad)) {
    *error = Named(poly, Text("yaw0_rad ", poly.yaw0_rad, " disagrees with the yaw polynomial at t = 0 (", yaw_at_0, ")"));
    return std::nullopt;
  }
  const MincoBoundary b = BoundaryOf(poly);
  std::optional<ArcYawTrajectory> trajectory;
  try {
    trajectory.emplace(poly.num_joints(), m, options.trajectory);
    trajectory->Update(poly.p0_W_m, b.head, b.tail, b.waypoints, b.durations_s);
  } catch (const std::exception& e) {
    *error = Named(poly, std::string("cannot solve its MINCO problem: ") + e.what());
    return std::nullopt;
  }
  const double relative = RelativeCoefficientError(poly, trajectory->minco().coefficients());
  if (!(relative <= options.coefficient_tolerance)) {
    *error = Named(poly, Text("not a MINCO s = 3 trajectory: the re-solved coefficients differ by ", relative,
                                     " relative to their size (tolerance ", options.coefficient_tolerance, ")"));
    return std::nullopt;
  }
  return trajectory;
}

}  // namespace topay::msgs
