#pragma once

#include <cmath>

#include "core/geometry/oriented_box.h"

namespace topay {

/// Grid on which generated scene and task numbers lie: 1e-6 (m or rad). Rounding every
/// generated number to it makes the JSON short, the JSON round trip exact (the nearest double
/// to a 6-decimal number prints back as that number) and the bytes of a seed's files immune to
/// last-bit differences of sin/cos between C libraries.
inline double QuantizeMicro(double value) { return std::round(value * 1e6) / 1e6; }

inline OrientedBox QuantizeMicro(const OrientedBox& box) {
  OrientedBox q;
  q.center_W_m = box.center_W_m.unaryExpr([](double v) { return QuantizeMicro(v); });
  q.size_m = box.size_m.unaryExpr([](double v) { return QuantizeMicro(v); });
  q.yaw_rad = QuantizeMicro(box.yaw_rad);
  return q;
}

}  // namespace topay
