#pragma once
// The localisation of the simulated robot: the true base pose plus a constant bias and seeded
// white noise (per measurement). With the defaults (all zero) it reports the truth.

#include <cstdint>

#include "core/common/random.h"

namespace topay {
class YamlSection;
}

namespace topay::sim {

struct PoseNoiseOptions {
  double xy_stddev_m = 0.0;     ///< white noise on x and y, std dev, m
  double yaw_stddev_rad = 0.0;  ///< white noise on yaw, std dev, rad
  double bias_x_m = 0.0;        ///< constant bias on x, m
  double bias_y_m = 0.0;        ///< constant bias on y, m
  double bias_yaw_rad = 0.0;    ///< constant bias on yaw, rad
};

/// Reads the keys above from `section` (all optional). Throws ConfigError for a negative std
/// dev or a non-finite value.
void ReadPoseNoiseOptions(YamlSection& section, PoseNoiseOptions* options);

struct PlanarPose {
  double x_m = 0.0, y_m = 0.0, yaw_rad = 0.0;
};

class PoseSensor {
 public:
  PoseSensor(const PoseNoiseOptions& options, std::uint64_t seed);
  /// One measurement of `truth` (yaw wrapped to (-pi, pi]). Draws 3 normals when noisy, none
  /// otherwise.
  PlanarPose Measure(const PlanarPose& truth);

 private:
  PoseNoiseOptions options_;
  Rng rng_;
};

}  // namespace topay::sim
