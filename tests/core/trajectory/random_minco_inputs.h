#pragma once

// Shared by the core/trajectory tests: random MINCO boundary data and central differences.

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Core>

#include "core/common/random.h"

namespace topay::testing {

/// Boundary data of MincoS3::Solve.
struct MincoInputs {
  Eigen::MatrixXd head;       // D x 3
  Eigen::MatrixXd tail;       // D x 3
  Eigen::MatrixXd waypoints;  // D x (M - 1)
  Eigen::VectorXd durations;  // M
};

inline Eigen::MatrixXd RandomMatrix(int rows, int cols, double low, double high, Rng* rng) {
  Eigen::MatrixXd m(rows, cols);
  for (int c = 0; c < cols; ++c) {
    for (int r = 0; r < rows; ++r) m(r, c) = rng->Uniform(low, high);
  }
  return m;
}

/// Positions in [-2, 2], velocities and accelerations in [-1, 1], durations in
/// [min_duration, max_duration] s.
inline MincoInputs RandomMincoInputs(int num_dims, int num_pieces, Rng* rng,
                                     double min_duration = 0.5, double max_duration = 2.5) {
  MincoInputs in;
  in.head = RandomMatrix(num_dims, 3, -1.0, 1.0, rng);
  in.tail = RandomMatrix(num_dims, 3, -1.0, 1.0, rng);
  in.head.col(0) = RandomMatrix(num_dims, 1, -2.0, 2.0, rng);
  in.tail.col(0) = RandomMatrix(num_dims, 1, -2.0, 2.0, rng);
  in.waypoints = RandomMatrix(num_dims, num_pieces - 1, -2.0, 2.0, rng);
  in.durations = RandomMatrix(num_pieces, 1, min_duration, max_duration, rng);
  return in;
}

/// Central difference (f(x + h) - f(x - h)) / 2h of a scalar function of one entry `value`,
/// restoring the entry afterwards.
inline double CentralDifference(double* value, double step, const std::function<double()>& f) {
  const double original = *value;
  *value = original + step;
  const double plus = f();
  *value = original - step;
  const double minus = f();
  *value = original;
  return (plus - minus) / (2.0 * step);
}

/// |a - b| / max(1, |b|).
inline double RelativeError(double analytic, double numeric) {
  return std::abs(analytic - numeric) / std::max(1.0, std::abs(numeric));
}

}  // namespace topay::testing
