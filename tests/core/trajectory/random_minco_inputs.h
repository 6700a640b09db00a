#pragma once

// Shared by the core/trajectory tests: random MINCO boundary data and central differences.

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/trajectory/minco_s3.h"

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

/// Expects every entry of `gradient` (waypoints, head, tail, durations) to match the central
/// difference of `value` with respect to the same entry of `in` (relative error < tolerance).
inline void ExpectMincoGradientMatchesFiniteDifferences(const MincoGradient& gradient,
                                                        MincoInputs* in,
                                                        const std::function<double()>& value,
                                                        double step, double tolerance) {
  const int num_dims = static_cast<int>(in->head.rows());
  const int num_pieces = static_cast<int>(in->durations.size());
  for (int d = 0; d < num_dims; ++d) {
    for (int i = 0; i + 1 < num_pieces; ++i) {
      EXPECT_LT(RelativeError(gradient.waypoints(d, i),
                              CentralDifference(&in->waypoints(d, i), step, value)),
                tolerance)
          << "d/dP(" << d << ", " << i << ")";
    }
    for (int k = 0; k < 3; ++k) {
      EXPECT_LT(RelativeError(gradient.head(d, k), CentralDifference(&in->head(d, k), step, value)),
                tolerance)
          << "d/dhead(" << d << ", " << k << ")";
      EXPECT_LT(RelativeError(gradient.tail(d, k), CentralDifference(&in->tail(d, k), step, value)),
                tolerance)
          << "d/dtail(" << d << ", " << k << ")";
    }
  }
  for (int j = 0; j < num_pieces; ++j) {
    EXPECT_LT(RelativeError(gradient.durations(j),
                            CentralDifference(&in->durations(j), step, value)),
              tolerance)
        << "d/dT(" << j << ")";
  }
}

}  // namespace topay::testing
