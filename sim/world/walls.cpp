#include "sim/world/walls.h"

#include "sim/integrators/integrator_info.h"
#include "sim/world/ball_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab::sim {
namespace {

// The range the centre of a ball may occupy along one axis, and which of its
// two walls are on. A ball wider than the box can only sit in the middle.
struct Axis {
    double lo;
    double hi;
    bool loOn;
    bool hiOn;
};

bool outside(const Axis& ax, double p)
{
    return (ax.loOn && p < ax.lo) || (ax.hiOn && p > ax.hi);
}

// Is the ball lying still on a wall and pressed against it? It started the
// sub-step touching the wall (p0 exactly on it, where every model puts a ball
// it stops) with no speed along the wall's normal (u0 = 0), and the
// integrator moved it onto or into the wall: the pull, not a fall, took it
// there. The wall then pushes back exactly as hard as the ball is pressed (a
// resting contact, not a bounce), so the ball does not move along this axis.
// Without this check every model bounced the speed the pull had added during
// the step, a h, although the ball never fell: from rest, clamp and mirror
// with verlet or rk4 climbed 78 px in 10 s, and exact walls with the Euler
// methods hopped for ever.
bool pressedWhileResting(const Axis& ax, double p0, double u0, double p, double u)
{
    if (u0 != 0.0)
        return false;
    if (ax.hiOn && p0 == ax.hi)
        return p > ax.hi || (p == ax.hi && u >= 0.0);
    if (ax.loOn && p0 == ax.lo)
        return p < ax.lo || (p == ax.lo && u <= 0.0);
    return false;
}

// clamp: put the ball on the wall it crossed; the overshoot is forgotten.
// A ball already moving away keeps its velocity.
void clampAxis(const Axis& ax, double e, double& p, double& u)
{
    if (ax.loOn && p < ax.lo) {
        p = ax.lo;
        if (u < 0.0)
            u = -e * u;
    } else if (ax.hiOn && p > ax.hi) {
        p = ax.hi;
        if (u > 0.0)
            u = -e * u;
    }
}

// reverse: the tutorial's first try. While the ball is past the wall its
// velocity is flipped; the position is left alone. A ball that starts partly
// outside flips every step and jitters on the wall.
void reverseAxis(const Axis& ax, double e, double p, double& u)
{
    if ((ax.loOn && p < ax.lo) || (ax.hiOn && p > ax.hi))
        u = -e * u;
}

// mirror: the distance travelled past the wall is travelled back into the box.
// Over a step the ball then moves as far as it would have, but the bounce
// happened at the wrong speed, so energy is gained or lost.
void mirrorAxis(const Axis& ax, double e, double& p, double& u)
{
    if (ax.loOn && p < ax.lo) {
        p = ax.lo + (ax.lo - p);
        if (u < 0.0)
            u = -e * u;
    } else if (ax.hiOn && p > ax.hi) {
        p = ax.hi - (p - ax.hi);
        if (u > 0.0)
            u = -e * u;
    }
    if (outside(ax, p)) // overshoot larger than the box: fall back to clamping
        clampAxis(ax, e, p, u);
}


// How a ball moved during the step, as the integrator sees it: from p0 it
// drifts as p(t) = p0 + d t + ½ a t², and its velocity at the end is
// d + a h + kick. Two shapes cover every integrator:
//  * a parabola (d = u0, a = (u1 − u0)/h, no kick): the exact path under a
//    constant force, which Verlet, rk4, rk45 and yoshida4 reproduce exactly
//    under gravity and to their order otherwise;
//  * kick and drift (Euler, semi-implicit Euler): these first-order methods
//    really move in a straight line at d = (p1 − p0)/h and change the
//    velocity in one kick; the rest of the velocity change is that kick.
//    Bouncing inside the straight drift keeps semi-implicit Euler symplectic,
//    so with e = 1 its energy error stays bounded instead of drifting.
//    Semi-implicit Euler is leapfrog with its velocities half a step late:
//    the speed it drifts at is the ball's velocity at mid-step.
struct PathInStep {
    double drift;      // d, px/s
    double accel;      // a, px/s²
    double endKick;    // px/s, added to the velocity at the end of the step
    double stepKick;   // px/s, u1 − u0: what the forces add to the velocity over the whole step
    bool kickDrift;    // the straight drift of the Euler methods
    bool midStepDrift; // the drift is the velocity at mid-step (semi-implicit Euler)
};

PathInStep stepPath(IntegratorKind kind, double p0, double u0, double p1, double u1, double h)
{
    const StepPath path = integratorInfo(kind).path;
    if (path == StepPath::KickDrift || path == StepPath::DriftKick) {
        const double d = (p1 - p0) / h;
        return {d, 0.0, u1 - d, u1 - u0, true, path == StepPath::KickDrift};
    }
    return {u0, (u1 - u0) / h, 0.0, u1 - u0, false, false};
}

// Semi-implicit Euler's drift after a bounce with e < 1. The drift d is the
// velocity at mid-step, so at the impact, `elapsed` into the step, the ball
// really moves at d less the kick still to come before mid-step; it leaves
// with e times that, and drifts on at the velocity its rebound has at
// mid-step. Reflecting d itself counts the kick of the rest of the step as
// part of the fall: a hop then gains e k (k up to one step's kick) at every
// bounce, and at dt = 1/240 s a ball dropped with e = 0.8 hopped for ever.
// With e = 1 the plain reflection of d is kept: it is symplectic, so the
// energy stays bounded, while this one drifts (2% in 6000 s at dt = 1/60 s
// in a one-ball script of the same step).
double midStepRebound(const PathInStep& path, double hitSpeed, double e, double elapsed, double h)
{
    const double kick = path.stepKick / h;  // px/s², along the axis
    const double toMid = 0.5 * h - elapsed; // s, from the impact to mid-step (negative: mid-step was before it)
    return -e * (hitSpeed - kick * toMid) + kick * toMid;
}

// Most bounces the exact model follows along one axis in one step. Only a
// ball crossing the box thousands of times a step with e just below 1 gets
// here (e = 1 repeats and is skipped in whole cycles, e < 1 under a pull
// towards the wall settles in closed form); it then stops at the wall it
// last left, moving away, and loses the rest of the step's path but no energy.
constexpr int kMaxBounces = 4096;

// exact: find when the edge touches a wall along the step's path, reverse the
// normal speed there (times e), and follow the path for the rest of the step,
// as often as the ball meets a wall again. Two motions need more than that:
//  * A ball pulled towards the wall it bounced off (gravity and the floor) with
//    e < 1 bounces ever lower: after a bounce at speed s it comes back after
//    2s/g, then after 2es/g, 2e²s/g, … All of these bounces together take
//    2s / (g (1 − e)), a finite time. If that time ends inside the step, the
//    ball has come to rest on the wall: it stays there with no normal speed.
//  * With e = 1 nothing is lost, so the motion repeats: from one bounce at a
//    wall to the next bounce at the same wall is one cycle of fixed length.
//    Whole cycles are skipped at once, so a very fast ball costs no more than
//    a slow one, and a hop of 0.01 px keeps hopping.
void exactAxis(const Axis& ax, double e, const PathInStep& path, double p0, double h, double& p, double& u,
               std::int64_t& hits)
{
    if (outside(ax, p0)) { // started outside (spawned there): nothing to solve
        clampAxis(ax, e, p, u);
        ++hits;
        return;
    }
    if (ax.lo == ax.hi) { // wedged between two walls: it cannot move along this axis
        p = ax.lo;
        hits += u != 0.0;
        u = 0.0;
        return;
    }
    const double a = path.accel;
    double start = p0, speed = path.drift, left = h;
    int cycleWall = -1;      // the wall whose first bounce started the cycle (0 low, 1 high)
    double cycleLeft = 0.0;  // s, time left in the step at that bounce
    std::int64_t cycleHits = 0;
    for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
        // The integrator's end point is outside (that is why we are here); after
        // a bounce, the path's end point decides.
        if (bounce > 0) {
            const double end = start + speed * left + 0.5 * a * left * left;
            if (!outside(ax, end)) {
                p = end;
                u = speed + a * left + path.endKick;
                return;
            }
        }
        const double tLo = ax.loOn ? wallContactTime(start, speed, a, ax.lo, -1.0, left) : std::nan("");
        const double tHi = ax.hiOn ? wallContactTime(start, speed, a, ax.hi, +1.0, left) : std::nan("");
        const bool hitLo = !std::isnan(tLo) && (std::isnan(tHi) || tLo <= tHi);
        const double t = hitLo ? tLo : tHi;
        if (std::isnan(t)) { // the path and the integrator disagree: fall back
            clampAxis(ax, e, p, u);
            ++hits;
            return;
        }
        const double hitSpeed = speed + a * t;
        start = hitLo ? ax.lo : ax.hi;
        speed = path.midStepDrift && e < 1.0 ? midStepRebound(path, hitSpeed, e, h - left + t, h) : -e * hitSpeed;
        left = std::max(0.0, left - t);
        if (hitSpeed == 0.0) { // touching with no speed: resting on the wall, not a bounce
            p = start;
            u = 0.0;
            return;
        }
        ++hits;

        // Pulled back towards this wall, and not reaching the other one?
        const double pull = hitLo ? -a : a; // px/s², acceleration towards the wall just hit
        const bool otherOn = hitLo ? ax.hiOn : ax.loOn;
        if (bouncesSettleWithin(speed, pull, e, otherOn, ax.hi - ax.lo, left)) {
            p = start;
            u = 0.0;
            return;
        }
        // The Euler methods cannot lift a ball off the wall by less than one
        // step's kick: a rebound slower than the kick towards this wall is
        // turned straight back into it by the next kick (semi-implicit Euler)
        // or by this step's end kick (Euler), before the ball has risen. Such
        // a bounce is the ball coming to rest. Without this the kick, a h,
        // kept a ball hopping for ever (e = 0.8: 0.22 px after 60 s), while
        // the real ball rests after t0 (1 + e) / (1 − e).
        const double kickTowards = hitLo ? -path.stepKick : path.stepKick; // px/s
        if (path.kickDrift && e < 1.0 && kickTowards > 0.0 && std::abs(speed) <= kickTowards &&
            !(otherOn && std::abs(speed) * left >= ax.hi - ax.lo)) {
            p = start;
            u = 0.0;
            return;
        }
        if (e == 1.0) {
            const int wall = hitLo ? 0 : 1;
            if (cycleWall < 0) {
                cycleWall = wall;
                cycleLeft = left;
                cycleHits = hits;
            } else if (wall == cycleWall && cycleLeft > left) {
                const double period = cycleLeft - left;
                const double cycles = std::min(std::floor(left / period), 1e15); // a count, not a physics limit
                hits += static_cast<std::int64_t>(cycles) * (hits - cycleHits);
                left = std::fmod(left, period);
                cycleWall = 2; // skipped once; follow the rest bounce by bounce
            }
        }
    }
    // Out of bounces: at the wall it last left, moving away from it.
    p = start;
    u = speed + path.endKick;
}

// The lowest centre position on the right of the middle wall. With the
// radius tested (r > 0) it is middle + r. Testing the centre only (r = 0)
// would make it the middle itself, a point on both sides: a ball from the
// right put back there was then taken to be on the left side (a start at
// x <= middle), and at the next step it went through the wall. The two sides
// must share no point, so the right side starts at the next number above the
// middle, 6e-14 px away at x = 300.
double rightOfMiddle(double middle, double r)
{
    return std::max(middle + r, std::nextafter(middle, std::numeric_limits<double>::infinity()));
}

} // namespace

bool bouncesSettleWithin(double speed, double pull, double e, bool otherWall, double span, double within)
{
    if (!(pull > 0.0 && e < 1.0) || (otherWall && speed * speed >= 2.0 * pull * span))
        return false;
    return 2.0 * std::abs(speed) / (pull * (1.0 - e)) <= within; // s, all bounces to come
}

// When does the ball touch `wall` while moving into it? The path is
// p(t) = p0 + u t + ½ a t²; `into` is +1 for the high wall (moving into it
// means dp/dt > 0) and −1 for the low wall. Returns the smallest such t in
// [0, tMax], or NaN. A root at which the ball moves away from the wall is not
// a contact: it is the moment the ball leaves the wall it has just bounced
// off. A root with zero speed counts only when the acceleration presses the
// ball into the wall (it rests there). The roots use the cancellation-free
// form of the quadratic formula: q = −½ (B + sign(B) √D), roots q / A and C / q.
double wallContactTime(double p0, double u, double a, double wall, double into, double tMax)
{
    const double A = 0.5 * a;
    const double B = u;
    const double C = p0 - wall;
    double best = std::numeric_limits<double>::quiet_NaN();
    auto consider = [&](double t) {
        if (!(t >= 0.0 && t <= tMax) || t >= best)
            return;
        const double towards = into * (u + a * t);
        if (towards > 0.0 || (towards == 0.0 && into * a > 0.0))
            best = t;
    };
    if (A == 0.0) {
        if (B != 0.0)
            consider(-C / B);
        return best;
    }
    const double disc = B * B - 4.0 * A * C;
    if (disc < 0.0)
        return best;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    if (q != 0.0) {
        consider(q / A);
        consider(C / q);
    } else {
        consider(0.0);
    }
    return best;
}

std::int64_t applyWalls(const WorldSettings& settings, const WallBalls& balls, const StepStart& start, double h,
                        Matrix2X& x, Matrix2X& v)
{
    const VectorX& radius = balls.radius;
    const WallSettings& walls = settings.walls;
    const BoxSettings& box = settings.box;
    const IntegratorKind integrator = settings.time.integrator;
    const Matrix2X& x0 = start.position;
    const Matrix2X& v0 = start.velocity;
    const bool on[2][2] = {{walls.left, walls.right}, {walls.top, walls.bottom}};
    const double size[2] = {box.width, box.height};
    const double wallE = walls.restitution;
    const double middle = 0.5 * box.width;
    // The world keeps the start of the sub-step whenever a wall is on
    // (walls.h); matrices of another size were not kept and are not read.
    const bool startKnown = x0.cols() == x.cols() && v0.cols() == x.cols();
    std::int64_t hits = 0;
    for (int d = 0; d < 2; ++d) {
        const bool middleHere = d == 0 && walls.middle;
        if (!on[d][0] && !on[d][1] && !middleHere)
            continue;
        for (Eigen::Index i = 0; i < x.cols(); ++i) {
            if (balls.pinned && balls.pinned[i]) // nothing moves it, not even a wall it overlaps
                continue;
            const double e = balls.restitution ? effectiveRestitution(balls.restitution[i], wallE) : wallE;
            // [code walls.test if world.walls.bottom=true: Where a wall stops a ball]
            // With centreOnly the wall test ignores the radius: the ball sinks
            // into the wall up to its centre before it turns.
            const double r = walls.centreOnly ? 0.0 : radius[i]; // [if world.centre_only=true]
            Axis ax{r, size[d] - r, on[d][0], on[d][1]};
            // [/code]
            if (middleHere) { // the middle wall bounds the side the ball started the step on
                if (x0(0, i) <= middle)
                    ax = Axis{ax.lo, middle - r, ax.loOn, true};
                else
                    ax = Axis{rightOfMiddle(middle, r), ax.hi, true, ax.hiOn};
            }
            if (ax.lo > ax.hi) // wider than the space it has
                ax.lo = ax.hi = 0.5 * (ax.lo + ax.hi);
            double& p = x(d, i);
            double& u = v(d, i);
            if (startKnown && pressedWhileResting(ax, x0(d, i), v0(d, i), p, u)) {
                p = x0(d, i);
                u = 0.0;
                continue;
            }
            if (!outside(ax, p))
                continue;
            ++hits;
            switch (walls.model) {
            case WallModel::Reverse:
                reverseAxis(ax, e, p, u);
                break;
            case WallModel::Clamp:
                clampAxis(ax, e, p, u);
                break;
            case WallModel::Mirror:
                mirrorAxis(ax, e, p, u);
                break;
            case WallModel::Exact:
                --hits; // exactAxis counts each bounce itself
                exactAxis(ax, e, stepPath(integrator, x0(d, i), v0(d, i), p, u, h), x0(d, i), h, p, u, hits);
                break;
            }
        }
    }
    return hits;
}

} // namespace forcelab::sim
