#include "sim/forces/noise.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace forcelab::sim {

GradientNoise1D::GradientNoise1D(std::uint64_t seed)
{
    std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
    for (double& s : m_slope)
        s = static_cast<double>(rng() >> 11) * 0x1.0p-52 - 1.0; // slope in [-1, 1)
}

double GradientNoise1D::operator()(double t) const
{
    const double cell = std::floor(t);
    const double f = t - cell;                                  // position inside the cell, [0, 1)
    const auto i = static_cast<std::int64_t>(cell);
    const double g0 = m_slope[static_cast<std::size_t>(i & 255)];
    const double g1 = m_slope[static_cast<std::size_t>((i + 1) & 255)];
    // Each corner contributes the line through it with its slope; the quintic
    // fade 6f⁵ − 15f⁴ + 10f³ blends them with zero first and second derivative
    // at the corners. The largest possible value is 0.5, so ×2 maps to [-1, 1].
    const double fade = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    const double v0 = g0 * f;
    const double v1 = g1 * (f - 1.0);
    return std::clamp(2.0 * (v0 + fade * (v1 - v0)), -1.0, 1.0);
}

} // namespace forcelab::sim
