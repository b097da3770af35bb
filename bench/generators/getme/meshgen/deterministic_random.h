#pragma once

// Random numbers that are identical on every standard library. std::mt19937_64's output sequence
// is fixed by the standard, but std::uniform_real_distribution's mapping is not (libstdc++ and
// libc++ consume and scale differently), so the mapping to [0, 1) is written out here.

#include <cstdint>
#include <random>

namespace getme::meshgen {

// Uniform in [0, 1): the top 53 bits of one engine draw, scaled by 2^-53 (exact in a double).
inline double UniformUnit(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// Uniform in [-1, 1).
inline double UniformSymmetric(std::mt19937_64& engine) { return 2.0 * UniformUnit(engine) - 1.0; }

}  // namespace getme::meshgen
