#pragma once

#include <cstdint>
#include <random>

namespace topay {

/// A seeded random number generator whose draws are the same on every platform and standard
/// library: it uses only the raw 64-bit output of std::mt19937_64 (fixed by the standard),
/// never the implementation-defined std::*_distribution classes. Same seed, same sequence.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1), 53 random bits.
  double Uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  /// Uniform in [low, high).
  double Uniform(double low, double high) { return low + (high - low) * Uniform01(); }

  /// Uniform integer in [low, high] (inclusive), without modulo bias worth noticing
  /// (64-bit multiply-shift).
  std::int64_t UniformInt(std::int64_t low, std::int64_t high);

  /// Standard normal draw (Box-Muller, no cached second value: the sequence stays simple).
  double Normal();

  /// A new seed derived from this generator, for seeding sub-generators (one per task, ...).
  std::uint64_t NextSeed() { return engine_(); }

  std::uint64_t NextRaw() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

/// Mixes two 64-bit values into a well-spread seed (splitmix64 finaliser), e.g. a base seed and
/// a task index: DeriveSeed(S, i).
std::uint64_t DeriveSeed(std::uint64_t seed, std::uint64_t index);

}  // namespace topay
