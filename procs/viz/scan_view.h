#pragma once
// A LiDAR scan as the viewer forwards it (docs/viewer.md: Scan): the points moved into W's axes
// relative to the sensor origin, every k-th kept so that at most max_points go, as int16
// centimetres (6 bytes a point instead of 12).

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "topay/point_cloud_t.hpp"

namespace topay::viz {

struct ScanViewOptions {
  /// Most points sent per scan (a uniform stride over the scan's order keeps its structure).
  int max_points = 4000;
};

/// The Scan payload; nullopt with *error naming the field if the message is inconsistent
/// (num_coords not a multiple of 3, a non-finite pose). Non-finite points and points farther
/// than 327 m from the sensor are left out.
std::optional<nlohmann::json> ScanPayload(const point_cloud_t& msg, const ScanViewOptions& options,
                                          std::string* error);

}  // namespace topay::viz
