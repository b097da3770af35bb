#pragma once

// Deterministic random elements and similarity maps. The uniform mapping is written out
// (53 high bits of mt19937_64 scaled to [0, 1)) so that results do not depend on the standard
// library's distribution implementation.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "getme/elements/element_quality.h"
#include "regular_elements.h"

namespace getme::test {

class UnitRandom {
 public:
  explicit UnitRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1).
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double low, double high) { return low + (high - low) * Uniform(); }

  // Nodes uniform in the unit cube (the paper's random elements, Section 2.2).
  template <ElementType kType>
  ElementNodes<kType> ElementInUnitCube() {
    ElementNodes<kType> nodes;
    for (Vec3& node : nodes) {
      const double x = Uniform();
      const double y = Uniform();
      const double z = Uniform();
      node = Vec3(x, y, z);
    }
    return nodes;
  }

  // Draws until an element is valid (Def. 2); counts the draws in *draws when given.
  template <ElementType kType>
  ElementNodes<kType> ValidElementInUnitCube(std::int64_t* draws = nullptr) {
    while (true) {
      const ElementNodes<kType> nodes = ElementInUnitCube<kType>();
      if (draws != nullptr) ++*draws;
      if (IsValid<kType>(nodes)) return nodes;
    }
  }

  // A rotation about a uniformly distributed axis by a uniform angle: det R = 1, R⁻¹ = Rᵗ.
  Eigen::Matrix3d Rotation() {
    const double z = Uniform(-1.0, 1.0);
    const double phi = Uniform(0.0, 2.0 * std::numbers::pi);
    const double r = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d axis(r * std::cos(phi), r * std::sin(phi), z);
    return Eigen::AngleAxisd(Uniform(0.0, 2.0 * std::numbers::pi), axis).toRotationMatrix();
  }

  // ζ log-uniform in [1/100, 100], t uniform in [-10, 10]³.
  Similarity RandomSimilarity() {
    Similarity similarity;
    similarity.scale = std::pow(10.0, Uniform(-2.0, 2.0));
    similarity.rotation = Rotation();
    const double x = Uniform(-10.0, 10.0);
    const double y = Uniform(-10.0, 10.0);
    const double z = Uniform(-10.0, 10.0);
    similarity.translation = Eigen::Vector3d(x, y, z);
    return similarity;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace getme::test
