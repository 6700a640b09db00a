#include "core/common/random.h"

#include <cmath>
#include <numbers>

namespace topay {

std::int64_t Rng::UniformInt(std::int64_t low, std::int64_t high) {
  const unsigned __int128 span = static_cast<unsigned __int128>(high - low) + 1;
  const unsigned __int128 product = static_cast<unsigned __int128>(engine_()) * span;
  return low + static_cast<std::int64_t>(product >> 64);
}

double Rng::Normal() {
  // Box-Muller; 1 - U keeps the logarithm's argument in (0, 1].
  const double u1 = 1.0 - Uniform01();
  const double u2 = Uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::uint64_t DeriveSeed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace topay
