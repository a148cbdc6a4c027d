#pragma once
// A force law written by the student as formulas (CustomForceSettings),
// compiled by muparser once per edit and evaluated for every ball at every
// force evaluation. The compiled law is kept per thread, keyed by its
// formulas, so a slider that changes a constant does not compile anything.

#include "sim/world/ball_state.h"
#include "sim/world/error.h"
#include "sim/world/world_settings.h"

#include <optional>

namespace forcelab::sim {

/// The names a formula may use besides the constants.
inline constexpr const char* kCustomVariables[] = {"x", "y", "vx", "vy", "m", "r", "q", "t", "W", "H"};

/// Checks the formulas and the constants, and that a potential belongs to
/// its force (F = −∇U at a few points of a `width` × `height` box). The
/// error's key path is the field (models.custom.fx, .fy, .potential or
/// .constants.NAME); a formula's message starts with the column of the
/// problem: "column 7: unknown name "kk"; …".
std::optional<Error> checkCustomForce(const CustomForceSettings& custom, double width, double height);

/// Adds the law's acceleration of every ball at (x, v, t) to a (the force
/// divided by each ball's mass, unless the formulas give the acceleration).
/// The settings must have passed checkCustomForce.
void addCustomAcceleration(const WorldSettings& settings, const BallState& balls, const Matrix2X& x,
                           const Matrix2X& v, double t, Matrix2X& a);

/// "the custom force (F_x = …, F_y = …)" for a message, each formula cut
/// to its first 60 characters with "…" when longer (a formula may be 2,000).
std::string describeCustomLaw(const CustomForceSettings& custom);

/// The potential energy of all balls at x (sum of U over the balls); 0 when
/// the law gives none.
double customPotential(const WorldSettings& settings, const BallState& balls, const Matrix2X& x);

/// The first ball at x where the law's potential U is not a number (NaN or
/// infinite), or -1. The load-time check samples U on a grid; a potential
/// may still be undefined between the samples (0*sqrt((x-291)*(x-293))), so
/// the world asks this after every step when the law has a U.
int firstBallWithoutPotential(const WorldSettings& settings, const BallState& balls, const Matrix2X& x);

} // namespace forcelab::sim
