#pragma once
// Basic linear-algebra types of the simulation core. World units: px and s,
// x to the right, y downwards (as on screen), so gravity points to +y.

#include <Eigen/Core>

#include <cstdint>

namespace forcelab::sim {

using Vec2 = Eigen::Vector2d;
/// One column per ball: row 0 is x, row 1 is y.
using Matrix2X = Eigen::Matrix2Xd;
using VectorX = Eigen::VectorXd;

/// A colour as 0xRRGGBB.
using Rgb = std::uint32_t;

} // namespace forcelab::sim
