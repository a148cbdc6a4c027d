#pragma once
// Continuous detection as an event-driven sub-step: every impact inside the
// step, ball–ball and ball–wall, in time order.
//
// Each ball follows the path the integrator gave it inside the step (as the
// exact wall model sees it, walls.cpp): p(t) = p₀ + u t + ½ a t², with
//  * a = (v₁ − v₀)/h and u chosen so that p(h) = p₁ for the integrators that
//    move on a parabola (Verlet, rk4, yoshida4, ...): exact under a constant force;
//  * a = 0 and u = (p₁ − p₀)/h for the Euler methods, which drift in a
//    straight line and change the velocity in one kick;
// and whatever the path leaves out of the end velocity v₁ is a kick added at
// the end. A ball with no impact ends exactly where the integrator put it.
//
// The loop: find the earliest impact of the step (two balls whose distance
// becomes r_a + r_b while they approach, or a ball reaching an enabled wall
// while moving into it), move the balls of that impact to its moment, change
// their velocities there (the response model for a pair, −e_w times the
// normal speed for a wall), and follow their new paths; the impacts they had
// planned are dropped and theirs are found again. Repeat until no impact is
// left before the end of the step.
//
// Honest limit: at most eventLimit(n) impacts per step (a pile pressed
// together by gravity makes ever smaller bounces: the resting solver, not
// this loop, is for piles). When the limit is reached the balls finish the
// step on their current paths and the caller's discrete pass resolves what
// then overlaps; the step reports it (limitReached).

#include "sim/world/ball_state.h"
#include "sim/world/world_settings.h"
#include "sim/collision/contact.h"

#include <cstdint>
#include <vector>

namespace forcelab::sim {

/// How the balls moved inside the step: their velocities at its start and the
/// integrator that moved them. Without start velocities every ball is taken
/// to move in a straight line from its start to its end position.
struct StepMotion {
    const Matrix2X* startVelocity = nullptr; ///< px/s, one column per ball
    IntegratorKind integrator = IntegratorKind::SemiImplicitEuler;
};

/// What one step of the loop did.
struct ImpactCounts {
    std::int64_t ballImpacts = 0; ///< ball–ball impacts resolved
    std::int64_t wallHits = 0;    ///< ball–wall bounces (and balls that came to rest on a wall)
    std::int64_t pairsTested = 0; ///< time-of-impact tests after the first (the broad phase counts its own)
    bool limitReached = false;    ///< eventLimit impacts were made and the rest of the step was not followed
};

class ImpactEvents {
public:
    /// Most impacts followed in one step for n balls: 16 per ball, and no more
    /// than 2·10⁷ / n so that the partner searches (n per impact) stay near
    /// 2·10⁷ box tests a step; at least 256.
    static std::int64_t eventLimit(int n);

    /// Reads each ball's path from `start` (positions at the start of the step)
    /// and the balls' current state (the integrator's end of the step).
    /// Returns, per ball, how far its path strays from the straight line
    /// between its ends (px): the broad phase grows each ball by it.
    const std::vector<double>& preparePaths(const BallState& balls, const Matrix2X& start, const StepMotion& motion,
                                            double h);

    /// Runs the impacts of the step. `candidates`: every pair whose paths may
    /// meet (the broad phase's swept pairs, radii grown by preparePaths'
    /// values), sorted by (a, b). `walls`: whether the enabled walls take part
    /// (exact wall model; otherwise the world has already bounced the balls
    /// off them and they are only kept from being pushed through). Writes the
    /// end of the step into balls and the pairs that met into `met`, sorted.
    ImpactCounts run(BallState& balls, const std::vector<Contact>& candidates, const CollisionSettings& settings,
                     const BoxSettings& box, const WallSettings& wallSettings, bool walls,
                     std::vector<Contact>& met);

private:
    struct Path {
        Vec2 p;       // px, position at time `from`
        Vec2 u;       // px/s, path velocity at time `from`
        Vec2 a;       // px/s², along the path
        Vec2 kick;    // px/s, added to the velocity at the end of the step
        Vec2 a0;      // px/s², the path's acceleration before the ball came to rest on a wall
        Vec2 kick0;   // px/s, the kick before that
        double from;  // s, into the step
        double lo[2]; // px, lowest centre coordinate the walls allow (axis x, y)
        double hi[2]; // px, highest
        bool on[2][2];     // [axis][low, high]: that wall bounds this ball
        bool resting[2];   // on a wall along this axis with no normal speed, for the rest of the step
        bool outside[2];   // started the step past a wall on this axis: clamped at the end instead
        Vec2 v0;      // px/s, velocity at the start of the step (NaN: not known)
        std::uint32_t version; // bumped at every change of path: planned impacts with an older one are dropped
        bool active;
        bool moved;            // had an impact this step
    };
    struct Event {
        double t;
        int a;  // ball
        int b;  // partner ball, or −1 − (2·axis + side) for a wall
        std::uint32_t va, vb;
    };
    static bool later(const Event& x, const Event& y);

    Vec2 positionAt(const Path& q, double t) const;
    Vec2 velocityAt(const Path& q, double t) const;
    void moveTo(Path& q, double t) const;
    void updateBox(int i);
    bool boxesMeet(int i, int j) const;
    void planWall(int i, double now);
    void planPair(int i, int j, double now);
    void planBall(int i, double now, int except);
    void push(const Event& e);
    void restIfPressed(Path& q, int k, double end);
    bool restsOnWall(int i, int k, int side, double now, double hitSpeed);
    void startPaths(const BallState& balls, const BoxSettings& box, const WallSettings& wallSettings, bool walls);
    void ballImpact(const BallState& balls, const Event& ev, double t, Response model, double e, bool walls,
                    std::vector<Contact>& met);
    void wallImpact(const Event& ev, double t);
    void finishPaths(BallState& balls, const BoxSettings& box, const WallSettings& wallSettings, bool walls);

    std::vector<Path> m_path;
    std::vector<double> m_bulge;
    std::vector<double> m_lo0, m_hi0, m_lo1, m_hi1; // box of each ball's path from now to the end: x lo/hi, y lo/hi
    std::vector<int> m_active;
    std::vector<Event> m_heap;
    std::vector<std::uint64_t> m_ignored; // pairs the response left approaching (naive models): not planned again
    const BallState* m_balls = nullptr;
    double m_h = 0.0;
    double m_wallE = 1.0;
    const double* m_ownE = nullptr; // per ball, its own restitution (BallState::ownRestitutions; nullptr: none)
    // The restitution ball i bounces off a wall with.
    double wallE(int i) const { return m_ownE ? effectiveRestitution(m_ownE[i], m_wallE) : m_wallE; }
    bool m_walls = false;
    ImpactCounts m_counts;
};

} // namespace forcelab::sim
