// Randomness that is the same on every machine: SplitMix64 and conversions that use only
// integer arithmetic and correctly rounded floating-point operations (no std::
// distributions, whose output the C++ standard leaves to the implementation).
#pragma once

#include "core/mesh.h"

#include <cstdint>
#include <string_view>

namespace holebench::generators {

/// FNV-1a, 64 bit: a stable hash of a case id.
constexpr std::uint64_t stable_hash(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  /// The next 64 random bits (SplitMix64, Steele, Lea and Flood 2014).
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  /// A unit vector uniform on the sphere, by rejection from the cube (only +, *, / and
  /// sqrt, which IEEE 754 rounds correctly: the same bits everywhere).
  Point unit_vector() {
    while (true) {
      const Point p(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0));
      const double n2 = p.sqrnorm();
      if (n2 > 1e-6 && n2 <= 1.0)
        return p / std::sqrt(n2);
    }
  }

 private:
  std::uint64_t state_;
};

}  // namespace holebench::generators
