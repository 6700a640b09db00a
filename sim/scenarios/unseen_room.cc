#include "sim/scenarios/unseen_room.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/keep_out.h"

namespace topay {

GeneratedScene UnseenTablesRoom(std::uint64_t seed, double keep_out_radius_m) {
  if (!(std::isfinite(keep_out_radius_m) && keep_out_radius_m >= 0.0)) {
    throw std::invalid_argument("UnseenTablesRoom: keep_out_radius_m must be finite and >= 0, got " +
                                std::to_string(keep_out_radius_m));
  }
  KeepOutRegions keep_out;
  if (keep_out_radius_m > 0.0) {  // as topay-sim does (procs/sim/sim_setup.cc)
    VerticalCylinder start;
    start.axis_W_m = Eigen::Vector2d::Zero();
    start.radius_m = keep_out_radius_m;
    start.bottom_z_m = 0.0;
    start.height_m = 3.0;
    keep_out.cylinders.push_back(start);
  }
  try {
    return GenerateTablesScene(seed, keep_out);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("Tables room of seed " + std::to_string(seed) + ": " + e.what());
  }
}

}  // namespace topay
