#pragma once
// Every setting of a world in one plain struct. The UI edits a copy and pushes
// the whole struct to the world between steps (World::setSettings), so a step
// never sees half an edit. A model whose `enabled` is false costs nothing: the
// step does not call it.

#include "sim/world/types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace forcelab::sim {

/// Reference ball used by the "radius" and "mass" scalings: a 10 px ball of
/// density 1. A ball of this size gets exactly the model's nominal
/// acceleration whatever the scaling, so switching scaling only changes how
/// smaller and larger balls differ from it.
inline constexpr double kReferenceRadius = 10.0;

enum class WallModel {
    Clamp,   ///< put the ball back on the wall; the overshoot is lost
    Mirror,  ///< reflect the overshoot back into the box
    Exact,   ///< find the time of impact inside the step, bounce, finish the step
    Reverse, ///< the first naive try: flip the velocity while past the wall, leave the position
};

struct BoxSettings {
    double width = 600.0;  ///< px
    double height = 400.0; ///< px
};

struct WallSettings {
    bool left = true;
    bool right = true;
    bool top = true;
    bool bottom = true;
    WallModel model = WallModel::Clamp;
    double restitution = 1.0; ///< 1, share of the normal speed a bounce keeps, [0, 1]
    bool middle = false;      ///< a vertical wall at x = width / 2; each ball stays on the side it is on
    bool centreOnly = false;  ///< test the ball's centre against the wall, not its edge (stage 3's bug)
};

struct GravitySettings {
    bool enabled = false;
    Vec2 g{0.0, 980.0}; ///< px/s², uniform acceleration (y down)

    /// px/s², the acceleration gravity gives now: g while on, zero while off.
    Vec2 acting() const { return enabled ? g : Vec2::Zero(); }
};

enum class ForceScale {
    None,   ///< every ball gets the same acceleration
    Radius, ///< acceleration × (reference radius / r)
    Mass,   ///< a force: acceleration × (reference mass / m)
};

enum class DragLaw {
    Linear,    ///< F = -k m_ref v
    Quadratic, ///< F = -k m_ref |v| v
};

/// Drag opposes the velocity. With scale Mass (the default) it is a force,
/// F = −k m_ref v (linear) or −k m_ref |v| v (quadratic), where m_ref is the
/// mass of the 10 px reference ball; a ball accelerates by F / m, so a heavy
/// ball slows down less and falls faster through air (terminal speed
/// g m / (k m_ref) for linear drag). k is how fast the reference ball slows.
/// Scale None is the tutorial's simpler model: every ball loses the same
/// share of its velocity, a = −k v, whatever its mass. Scale Radius divides by
/// r / r_ref instead: quadratic air drag on equal-density spheres (force ∝ r²,
/// mass ∝ r³).
struct DragSettings {
    bool enabled = false;
    DragLaw law = DragLaw::Linear;
    double k = 0.1;                       ///< 1/s for linear drag, 1/px for quadratic drag (reference ball)
    ForceScale scale = ForceScale::Mass;  ///< how the drag on a ball depends on its size
};

enum class WindMode { Off, Random, Smoothed, Noise, Pointer };

struct WindSettings {
    WindMode mode = WindMode::Off;
    double strength = 50.0;        ///< px/s², largest horizontal acceleration of a reference ball
    ForceScale scale = ForceScale::None;
    double smoothedStep = 0.1;     ///< 1, largest change per step of the smoothed wind, as a share of strength
    double noiseFrequency = 0.5;   ///< Hz, how fast the noise wind changes
    WindMode compare = WindMode::Off; ///< a second mode computed beside the first for a second vane; acts on nothing
};

/// Stage 10: a random acceleration per ball, centred on zero.
struct RandomAccelSettings {
    bool enabled = false;
    bool fixed = false;      ///< false: a new value every step; true: one value per ball, kept for ever
    double strength = 100.0; ///< px/s², largest value of each component
    /// The course's Math.random() bug: each component is drawn in
    /// [0, strength) px/s² instead of [−strength, strength), so on average
    /// every ball is pushed by (strength/2, strength/2) px/s², right and down.
    /// The same draws as the centred kind: u in [0, 1) gives strength·u
    /// here and strength·(2u − 1) there.
    bool uncentred = false;
};

enum class PointKind { Attract, Repel };

struct PointForceSettings {
    bool enabled = false;
    PointKind kind = PointKind::Attract;
    Vec2 position{300.0, 200.0}; ///< px
    double strength = 1e6;       ///< px³/s², a = strength / d² for a reference ball
    double maxAccel = 0.0;       ///< px/s², clamp on the acceleration; 0 = no clamp
    ForceScale scale = ForceScale::None;
    /// The course's un-normalised repulsion bug: the difference vector
    /// d = x − p itself is multiplied by strength / |d|² instead of the unit
    /// vector d / |d|, so a = ±strength d / |d|², of size strength / |d|
    /// (px/s² with strength in px³/s²: one power of d short), a 1/d law
    /// where the lesson's is 1/d². Attract and repel alike; the clamp
    /// still bounds the size.
    bool unnormalised = false;
};

struct SpringSettings {
    bool enabled = false;
    Vec2 anchor{300.0, 200.0}; ///< px
    double k = 4.0;            ///< 1/s², stiffness per unit mass: a = -k (x - anchor), ω = √k
};

struct MutualGravitySettings {
    bool enabled = false;
    double G = 1000.0;     ///< px³/(mass·s²); negative pushes every pair apart
    double softening = 0.0; ///< px, ε in F = G m₁ m₂ r / (r² + ε²)^(3/2) (Plummer: smooth at r = 0)
};

struct HomingSettings {
    bool enabled = false;
    double strength = 5.0; ///< 1/s², a = strength × (home - x), a spring to the ball's home
};

/// A uniform magnetic field B out of the screen: F = q v × B, which turns
/// every moving charge without changing its speed. In the plane, with y down,
/// a = (q / m) m₁₀ B (v_y, −v_x), scaled like drag so that the 10 px ball
/// with charge 1 circles at ω = B; a ball of mass m and charge q circles at
/// ω = q B m₁₀ / m, on a circle of radius r = v / ω = m v / (q B m₁₀).
struct MagneticSettings {
    bool enabled = false;
    double B = 1.0; ///< rad/s, how fast the 10 px reference ball with charge 1 turns
};

struct PointerSettings {
    bool enabled = false;
    double strength = 2e6; ///< px³/s², inverse-square pull (hover) or push (pressed)
    double maxAccel = 3000.0; ///< px/s², clamp near the pointer; 0 = no clamp
};

struct SpeedLimitSettings {
    bool enabled = false;
    double max = 800.0; ///< px/s
};

enum class Detection { Brute, Halved, Sweep, Grid };
enum class Response { None, Flag, Reverse1D, Elastic1D, Axis2D, Impulse2D };

struct CollisionSettings {
    Detection detection = Detection::Sweep;
    Response response = Response::None; ///< None: the collision stage is skipped entirely
    double restitution = 1.0;           ///< 1, ball–ball restitution e, [0, 1]
    bool continuous = false;            ///< find the time of impact inside the step
    /// under gravity, 2d-impulse also solves resting contact (contact_solver.h:
    /// several passes, a bounce threshold, speculative contacts), so piles stand;
    /// false: the one textbook pass, as without gravity
    bool resting = true;
};

enum class IntegratorKind { Euler, SemiImplicitEuler, Verlet, Rk4, Yoshida4, Rk45, Exact, Ias15 };

struct TimeSettings {
    IntegratorKind integrator = IntegratorKind::SemiImplicitEuler;
    double dt = 1.0 / 60.0;   ///< s, one step of the world
    int substeps = 1;         ///< 1, a step is split into this many equal sub-steps
    double tolerance = 1e-9;  ///< 1, rk45 local error tolerance (absolute and relative); ias15 error per sub-step (|b₆| / |a|)
    std::uint64_t seed = 1;   ///< random generator seed (wind, random acceleration, spawning)
    bool perFrame = false;    ///< ignore dt: each step moves the balls as if 1/60 s had passed (stage 5's bug)
    /// Let a fixed step jump past what it cannot follow (a close pass of an
    /// unclamped 1/d² pull, a custom force stiffer than the step) instead of
    /// stopping there: stage 17's slingshot bug.
    bool stepPastClosePasses = false;
};

/// The length of one "frame" of the per-frame bug, s.
inline constexpr double kFrameSeconds = 1.0 / 60.0;

/// A named number a student's force law uses (k, c, B, …), with the range of its slider.
struct CustomConstant {
    std::string name;   ///< letters, digits and _, starting with a letter; not one of the law's variables
    double value = 0.0; ///< in whatever unit the law gives it
    double min = 0.0;   ///< slider range
    double max = 1.0;
    friend bool operator==(const CustomConstant&, const CustomConstant&) = default;
};

/// A force law the student writes as formulas (sim/forces/custom_force.h). The
/// formulas may use the ball's x, y (px), vx, vy (px/s), m (mass), r (px),
/// q (charge), the time t (s), the box's W and H (px), pi and the constants.
struct CustomForceSettings {
    bool enabled = false;
    bool acceleration = false; ///< the formulas give the acceleration (px/s²) instead of the force (mass·px/s²)
    std::string fx = "0";      ///< F_x (or a_x) as a formula
    std::string fy = "0";      ///< F_y (or a_y) as a formula
    /// Optional: the potential energy U (mass·px²/s²) of a conservative law,
    /// F = −∇U; given, the accounting counts it as potential energy instead
    /// of booking the law's work.
    std::string potential;
    std::vector<CustomConstant> constants;
};

struct WorldSettings {
    BoxSettings box;
    WallSettings walls;
    TimeSettings time;
    GravitySettings gravity;
    DragSettings drag;
    WindSettings wind;
    RandomAccelSettings randomAccel;
    PointForceSettings point;
    SpringSettings spring;
    MutualGravitySettings mutualGravity;
    HomingSettings homing;
    PointerSettings pointer;
    MagneticSettings magnetic;
    SpeedLimitSettings speedLimit;
    CollisionSettings collisions;
    CustomForceSettings custom;
};

} // namespace forcelab::sim
