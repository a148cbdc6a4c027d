#pragma once
// The state of N balls, stored as columns so that hot loops are whole-array
// expressions: positions and velocities are 2×N, the per-ball scalars are
// vectors of length N. Ball i is column / entry i everywhere.

#include "sim/world/types.h"

#include <algorithm>
#include <span>
#include <vector>

namespace forcelab::sim {

/// Most balls a world holds: spawning and lesson files are checked against it.
inline constexpr int kMaxBalls = 200'000;

/// Sizes and masses a ball may have. Below 1e-6 px a density-1 sphere's mass
/// (4.19e-18) is still a normal double; a radius of 1e-110 px gave a mass of
/// exactly 0 (r³ underflows), which no force can move. A mass below 1e-12
/// would make 1/m overflow with the impulses of a fast collision.
inline constexpr double kMinRadius = 1e-6; ///< px
inline constexpr double kMaxRadius = 1e4;  ///< px
inline constexpr double kMinMass = 1e-12;  ///< mass units
inline constexpr double kMaxMass = 1e15;   ///< mass units
inline constexpr double kMaxCharge = 1e6;  ///< charge units, either sign

/// A ball's restitution when it has none of its own: the world's applies
/// (models.collisions.restitution against balls, world.restitution against walls).
inline constexpr double kWorldRestitution = -1.0;

/// Whether `own` is a ball's own restitution rather than kWorldRestitution.
inline bool hasOwnRestitution(double own) { return own >= 0.0; }

/// The restitution a ball bounces with: its own if it has one, else `world`.
inline double effectiveRestitution(double own, double world) { return own >= 0.0 ? own : world; }

/// The restitution of two balls that hit: the smaller of their effective ones
/// (a ball of clay stops a rubber ball's bounce too).
inline double pairRestitution(double ownA, double ownB, double world)
{
    return std::min(effectiveRestitution(ownA, world), effectiveRestitution(ownB, world));
}

/// Density of the default mass: m = density × (4/3) π r³ (equal-density spheres).
inline constexpr double kDefaultDensity = 1.0;

/// Mass of an equal-density sphere of radius r (density 1).
double sphereMass(double radius);

/// One ball as a plain value, for building and inspecting a state.
struct Ball {
    Vec2 position{0.0, 0.0}; ///< px
    Vec2 velocity{0.0, 0.0}; ///< px/s
    double radius = 10.0;    ///< px
    double mass = 0.0;       ///< mass units; 0 means sphereMass(radius)
    Rgb color = 0x5080e0;
    Vec2 home{0.0, 0.0};     ///< px, where homing pulls this ball
    double charge = 1.0;     ///< charge units; what a magnetic field acts on (1: like the 10 px reference ball)
    /// A pinned ball never moves: no force, wall or collision changes its
    /// position, and its velocity stays zero. Other balls bounce off it as
    /// off a ball of infinite mass.
    bool pinned = false;
    /// 1, this ball's own restitution e in [0, 1] against walls and balls;
    /// kWorldRestitution (the default): the world's.
    double restitution = kWorldRestitution;
};

struct BallState {
    Matrix2X position; ///< px
    Matrix2X velocity; ///< px/s
    VectorX radius;    ///< px
    VectorX mass;      ///< mass units (density 1 sphere of radius r by default)
    /// 1/mass, kept in step with mass; 0 for a pinned ball (an impulse
    /// cannot move it), so the collision stages need no test of their own.
    VectorX inverseMass;
    std::vector<Rgb> color;
    Matrix2X home;     ///< px, home of each ball's colour (homing)
    VectorX charge;    ///< charge units, per ball
    /// Set by the collision stage: 1 if the ball touches another ball this step.
    std::vector<unsigned char> colliding;
    /// 1 for a pinned ball (Ball::pinned); see anyPinned().
    std::vector<unsigned char> pinned;
    /// 1, each ball's own restitution, or kWorldRestitution; see ownRestitutions().
    VectorX restitution;

    int size() const { return static_cast<int>(position.cols()); }
    bool empty() const { return size() == 0; }

    void clear();
    /// Resizes to n balls; new entries are zero and must be filled by the caller.
    void resize(int n);
    /// Replaces the state with these balls; a mass of 0 becomes sphereMass(radius).
    void assign(std::span<const Ball> balls);
    /// Appends one ball (O(N): for spawning one ball at a time, not for building).
    void append(const Ball& ball);
    /// Inserts one ball before index i (0 ≤ i ≤ size()); the balls from i on
    /// move up by one. O(N): for editing a scene by hand.
    void insert(int i, const Ball& ball);
    /// Removes ball i; the balls after it move down by one. O(N).
    void remove(int i);
    /// Writes ball i; a mass of 0 becomes sphereMass(radius), and a pinned
    /// ball's velocity 0.
    void set(int i, const Ball& ball);
    Ball ball(int i) const;
    void setMass(int i, double mass);
    /// Pins ball i (its velocity and inverse mass become 0) or frees it
    /// (its inverse mass is 1/mass again).
    void setPinned(int i, bool on);
    /// Whether any ball is pinned: one scan of a byte per ball, so the step
    /// asks once and scenes without pins pay nothing else.
    bool anyPinned() const;
    /// restitution's entries, or nullptr when no ball has its own (the
    /// collision stages then use the world's values as they are): one scan.
    const double* ownRestitutions() const;
};

} // namespace forcelab::sim
