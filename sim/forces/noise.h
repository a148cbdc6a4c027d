#pragma once
// Smooth gradient noise in one dimension (Perlin's construction): a random
// slope at every whole number, blended with a quintic fade, so the value and
// its first two derivatives are continuous. Values lie in about [-0.5, 0.5];
// noise(t) * 2 is used as a value in [-1, 1].

#include <array>
#include <cstdint>

namespace forcelab::sim {

class GradientNoise1D {
public:
    GradientNoise1D() : GradientNoise1D(1) {}
    explicit GradientNoise1D(std::uint64_t seed);
    /// Noise at t, in [-1, 1] after scaling; 0 at every whole number.
    double operator()(double t) const;

private:
    std::array<double, 256> m_slope{};
};

} // namespace forcelab::sim
