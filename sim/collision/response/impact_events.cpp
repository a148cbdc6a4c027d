// Continuous detection: every impact of a step in time order (impact_events.h).

#include "sim/collision/response/impact_events.h"

#include "sim/integrators/integrator_info.h"
#include "sim/world/walls.h"
#include "sim/collision/response/positional_correction.h"
#include "sim/collision/response/response.h"
#include "sim/collision/response/time_of_impact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab::sim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The polynomial f(s) = Σ k[i] sⁱ (degree 4) shifted to s = a + x: the
// coefficients m of f(a + x) = Σ m[i] xⁱ (repeated synthetic division).
void shift(const double k[5], double a, double m[5])
{
    for (int i = 0; i < 5; ++i)
        m[i] = k[i];
    for (int i = 0; i < 4; ++i)
        for (int j = 3; j >= i; --j)
            m[j] += a * m[j + 1];
}

double evaluate(const double k[5], double s)
{
    return (((k[4] * s + k[3]) * s + k[2]) * s + k[1]) * s + k[0];
}

// First s in (0, sMax] with f(s) <= 0 for f(0) > 0, or NaN. Intervals are
// searched left first and dropped when a lower bound of f over them (the
// shifted coefficients, each negative one at its worst) is positive; a root
// is pinned to 1e-13 of the step. A dip below zero narrower than that is
// missed: the pair then grazes by less than a rounding error.
double firstRoot(const double k[5], double sMax)
{
    struct Span {
        double lo, hi;
    };
    Span stack[128];
    int top = 0;
    stack[top++] = {0.0, sMax};
    const double resolution = 1e-13 * sMax;
    for (int visits = 0; top > 0 && visits < 20000; ++visits) {
        const Span span = stack[--top];
        double m[5];
        shift(k, span.lo, m);
        const double w = span.hi - span.lo;
        double bound = m[0], power = 1.0;
        for (int i = 1; i < 5; ++i) {
            power *= w;
            bound += std::min(0.0, m[i]) * power;
        }
        if (bound > 0.0)
            continue;
        if (w <= resolution) {
            if (evaluate(k, span.hi) <= 0.0)
                return span.hi;
            continue;
        }
        const double mid = span.lo + 0.5 * w;
        if (top + 2 > 128)
            return kNaN;
        stack[top++] = {mid, span.hi}; // right half after the left one
        stack[top++] = {span.lo, mid};
    }
    return kNaN;
}

std::uint64_t pairKey(int a, int b)
{
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

} // namespace

std::int64_t ImpactEvents::eventLimit(int n)
{
    const std::int64_t count = std::max(n, 1);
    return std::max<std::int64_t>(256, std::min<std::int64_t>(16 * count, 20'000'000 / count));
}

bool ImpactEvents::later(const Event& x, const Event& y)
{
    if (x.t != y.t)
        return x.t > y.t;
    if (x.a != y.a)
        return x.a > y.a;
    return x.b > y.b;
}

Vec2 ImpactEvents::positionAt(const Path& q, double t) const
{
    const double s = t - q.from;
    return q.p + s * q.u + (0.5 * s * s) * q.a;
}

Vec2 ImpactEvents::velocityAt(const Path& q, double t) const
{
    return q.u + (t - q.from) * q.a;
}

void ImpactEvents::moveTo(Path& q, double t) const
{
    q.p = positionAt(q, t);
    q.u = velocityAt(q, t);
    q.from = t;
}

const std::vector<double>& ImpactEvents::preparePaths(const BallState& balls, const Matrix2X& start,
                                                      const StepMotion& motion, double h)
{
    const int n = balls.size();
    m_h = h;
    m_path.assign(static_cast<std::size_t>(n), Path{});
    m_bulge.assign(static_cast<std::size_t>(n), 0.0);
    const bool parabola = motion.startVelocity && motion.startVelocity->cols() == n &&
                          integratorInfo(motion.integrator).path == StepPath::Parabola;
    for (int i = 0; i < n; ++i) {
        Path& q = m_path[static_cast<std::size_t>(i)];
        const Vec2 p0 = start.col(i), p1 = balls.position.col(i), v1 = balls.velocity.col(i);
        q.p = p0;
        q.from = 0.0;
        q.a = parabola ? Vec2((v1 - motion.startVelocity->col(i)) / h) : Vec2::Zero();
        // u such that the path ends at p1 exactly: p0 + u h + ½ a h² = p1.
        q.u = (p1 - p0) / h - (0.5 * h) * q.a;
        q.kick = v1 - (q.u + h * q.a);
        q.v0 = motion.startVelocity && motion.startVelocity->cols() == n ? Vec2(motion.startVelocity->col(i))
                                                                         : Vec2::Constant(kNaN);
        q.a0 = q.a;
        q.kick0 = q.kick;
        q.version = 0;
        q.moved = false;
        q.active = p0.allFinite() && p1.allFinite() && v1.allFinite() && q.u.allFinite() && q.a.allFinite() &&
                   std::isfinite(balls.radius[i]) && balls.radius[i] >= 0.0;
        // A parabola strays at most |a| h²/8 from its chord; a hair more for rounding.
        const double bulge = 0.125 * q.a.norm() * h * h;
        m_bulge[static_cast<std::size_t>(i)] =
            q.active ? bulge + 1e-9 * (bulge + balls.radius[i] + p0.cwiseAbs().maxCoeff() + p1.cwiseAbs().maxCoeff())
                     : 0.0;
    }
    return m_bulge;
}

void ImpactEvents::updateBox(int i)
{
    const auto k = static_cast<std::size_t>(i);
    const Path& q = m_path[k];
    const double r = m_balls->radius[i];
    const double left = m_h - q.from;
    double lo[2], hi[2];
    for (int d = 0; d < 2; ++d) {
        const double e = q.p[d] + left * q.u[d] + 0.5 * left * left * q.a[d];
        lo[d] = std::min(q.p[d], e);
        hi[d] = std::max(q.p[d], e);
        if (q.a[d] != 0.0) { // the turning point of the parabola, if it is inside
            const double s = -q.u[d] / q.a[d];
            if (s > 0.0 && s < left) {
                const double v = q.p[d] + s * q.u[d] + 0.5 * s * s * q.a[d];
                lo[d] = std::min(lo[d], v);
                hi[d] = std::max(hi[d], v);
            }
        }
        const double pad = r + 1e-9 * (std::abs(lo[d]) + std::abs(hi[d]) + r) + 1e-300;
        lo[d] -= pad;
        hi[d] += pad;
    }
    m_lo0[k] = lo[0];
    m_hi0[k] = hi[0];
    m_lo1[k] = lo[1];
    m_hi1[k] = hi[1];
}

bool ImpactEvents::boxesMeet(int i, int j) const
{
    const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
    return m_lo0[a] <= m_hi0[b] && m_lo0[b] <= m_hi0[a] && m_lo1[a] <= m_hi1[b] && m_lo1[b] <= m_hi1[a];
}

void ImpactEvents::push(const Event& e)
{
    m_heap.push_back(e);
    std::push_heap(m_heap.begin(), m_heap.end(), later);
}

void ImpactEvents::planWall(int i, double now)
{
    if (!m_walls)
        return;
    const Path& q = m_path[static_cast<std::size_t>(i)];
    const double left = m_h - now;
    const Vec2 p = positionAt(q, now), u = velocityAt(q, now);
    double best = kNaN;
    int code = 0;
    for (int k = 0; k < 2; ++k) {
        if (q.resting[k] || q.outside[k])
            continue;
        for (int side = 0; side < 2; ++side) {
            if (!q.on[k][side])
                continue;
            const double s = wallContactTime(p[k], u[k], q.a[k], side ? q.hi[k] : q.lo[k], side ? 1.0 : -1.0, left);
            if (s < best || (std::isnan(best) && !std::isnan(s))) {
                best = s;
                code = 2 * k + side;
            }
        }
    }
    if (!std::isnan(best))
        push(Event{now + best, i, -1 - code, q.version, 0});
}

void ImpactEvents::planPair(int i, int j, double now)
{
    const int a = std::min(i, j), b = std::max(i, j);
    if (!m_ignored.empty() && std::binary_search(m_ignored.begin(), m_ignored.end(), pairKey(a, b)))
        return;
    ++m_counts.pairsTested;
    const Path& qa = m_path[static_cast<std::size_t>(a)];
    const Path& qb = m_path[static_cast<std::size_t>(b)];
    const double left = m_h - now;
    const Vec2 d0 = positionAt(qb, now) - positionAt(qa, now);
    const Vec2 dv = velocityAt(qb, now) - velocityAt(qa, now);
    const Vec2 c = 0.5 * (qb.a - qa.a);
    const double s2 = m_balls->radius[a] + m_balls->radius[b];
    double s = kNaN;
    // |d0 + dv s + c s²|² − S², a quartic in s.
    const double len = d0.norm();
    const double k[5] = {(len - s2) * (len + s2), 2.0 * d0.dot(dv), dv.dot(dv) + 2.0 * d0.dot(c), 2.0 * dv.dot(c),
                         c.dot(c)};
    if ((c.x() == 0.0 && c.y() == 0.0) || !std::isfinite(k[0] + k[1] + k[2] + k[3] + k[4])) {
        // Straight relative motion (no forces, or the same acceleration for
        // both, as under uniform gravity): the closed form. (Also the
        // fallback for accelerations too large to square.)
        const double t = timeOfImpact(d0.x(), d0.y(), dv.x() * left, dv.y() * left, s2);
        if (t >= 0.0)
            s = t * left;
    } else {
        s = k[0] < 0.0 ? 0.0 : firstRoot(k, left);
    }
    if (std::isnan(s))
        return;
    // Only an approach is an impact: a pair that touches while moving apart
    // (it has just bounced) is left alone. The tolerance is the rounding of an
    // impulse that has just stopped the pair (e = 0).
    const Vec2 d = d0 + s * dv + (s * s) * c;
    const double vn = (dv + (2.0 * s) * c).dot(d);
    const double speeds = velocityAt(qa, now).norm() + velocityAt(qb, now).norm();
    if (!(vn < -1e-12 * speeds * d.norm()))
        return;
    push(Event{now + s, a, b, qa.version, qb.version});
}

void ImpactEvents::planBall(int i, double now, int except)
{
    for (const int j : m_active)
        if (j != i && j != except && boxesMeet(i, j))
            planPair(i, j, now);
}

bool ImpactEvents::restsOnWall(int i, int k, int side, double now, double hitSpeed)
{
    // Like the exact wall model: a ball that touches with no speed rests; one
    // pulled back to the wall with e < 1 that cannot reach the other wall
    // bounces ever lower, 2 s / (g (1 − e)) in all for a bounce at speed s,
    // and if that ends inside the step it rests on the wall from now on.
    const Path& q = m_path[static_cast<std::size_t>(i)];
    if (hitSpeed == 0.0)
        return true;
    const double pull = side ? q.a[k] : -q.a[k]; // px/s², towards this wall
    const double e = wallE(i);
    return bouncesSettleWithin(e * std::abs(hitSpeed), pull, e, q.on[k][1 - side], q.hi[k] - q.lo[k],
                               m_h - now);
}

void ImpactEvents::restIfPressed(Path& q, int k, double end)
{
    // A ball lying still on a wall (on it at the start with no normal speed)
    // that the pull moved onto or into it is pressed, not falling: the wall
    // holds it for the whole step, as in the wall stage (walls.cpp). Without
    // this the Euler methods, which drift at the speed the pull added, would
    // bounce it off the wall every step.
    if (q.v0[k] != 0.0)
        return; // moving, or not known (NaN)
    const bool onHigh = q.on[k][1] && q.p[k] == q.hi[k] && end >= q.hi[k];
    const bool onLow = q.on[k][0] && q.p[k] == q.lo[k] && end <= q.lo[k];
    if (!onHigh && !onLow)
        return;
    q.resting[k] = true;
    q.u[k] = 0.0;
    q.a[k] = 0.0;
    q.kick[k] = 0.0;
    q.moved = true;
}

ImpactCounts ImpactEvents::run(BallState& balls, const std::vector<Contact>& candidates,
                               const CollisionSettings& settings, const BoxSettings& box,
                               const WallSettings& wallSettings, bool walls, std::vector<Contact>& met)
{
    const int n = balls.size();
    const auto count = static_cast<std::size_t>(n);
    m_balls = &balls;
    m_walls = walls;
    m_wallE = wallSettings.restitution;
    m_ownE = balls.ownRestitutions();
    m_counts = ImpactCounts{};
    m_heap.clear();
    m_ignored.clear();
    m_active.clear();
    met.clear();
    m_lo0.assign(count, 0.0);
    m_hi0.assign(count, 0.0);
    m_lo1.assign(count, 0.0);
    m_hi1.assign(count, 0.0);
    startPaths(balls, box, wallSettings, walls);
    for (const Contact& c : candidates)
        if (m_path[static_cast<std::size_t>(c.a)].active && m_path[static_cast<std::size_t>(c.b)].active)
            planPair(c.a, c.b, 0.0);
    for (const int i : m_active)
        planWall(i, 0.0);

    const std::int64_t limit = eventLimit(n);
    std::int64_t events = 0;
    const double e = settings.restitution;
    while (!m_heap.empty()) {
        std::pop_heap(m_heap.begin(), m_heap.end(), later);
        const Event ev = m_heap.back();
        m_heap.pop_back();
        Path& qa = m_path[static_cast<std::size_t>(ev.a)];
        if (qa.version != ev.va || (ev.b >= 0 && m_path[static_cast<std::size_t>(ev.b)].version != ev.vb))
            continue; // planned on a path the ball has left since
        if (events >= limit) {
            m_counts.limitReached = true;
            break;
        }
        ++events;
        const double t = std::min(ev.t, m_h);
        if (ev.b >= 0)
            ballImpact(balls, ev, t, settings.response, e, walls, met);
        else
            wallImpact(ev, t);
    }
    finishPaths(balls, box, wallSettings, walls);
    std::sort(met.begin(), met.end(), [](const Contact& l, const Contact& r) { return l.a < r.a || (l.a == r.a && l.b < r.b); });
    met.erase(std::unique(met.begin(), met.end()), met.end());
    m_balls = nullptr;
    return m_counts;
}

// Each active ball's path at the start of the step: the range its centre
// may take between the walls, and whether it rests on one.
void ImpactEvents::startPaths(const BallState& balls, const BoxSettings& box, const WallSettings& wallSettings,
                              bool walls)
{
    const int n = balls.size();
    const bool on[2][2] = {{wallSettings.left, wallSettings.right}, {wallSettings.top, wallSettings.bottom}};
    const double size[2] = {box.width, box.height};
    const double middle = 0.5 * box.width;
    for (int i = 0; i < n; ++i) {
        Path& q = m_path[static_cast<std::size_t>(i)];
        if (!q.active)
            continue;
        m_active.push_back(i);
        // The range each coordinate of the centre may take, as in walls.cpp.
        const double r = wallSettings.centreOnly ? 0.0 : balls.radius[i];
        for (int k = 0; k < 2; ++k) {
            q.lo[k] = r;
            q.hi[k] = size[k] - r;
            q.on[k][0] = on[k][0];
            q.on[k][1] = on[k][1];
            if (k == 0 && wallSettings.middle) { // the middle wall bounds the side the ball started on
                if (q.p.x() <= middle) {
                    q.hi[0] = middle - r;
                    q.on[0][1] = true;
                } else {
                    q.lo[0] = middle + r;
                    q.on[0][0] = true;
                }
            }
            if (q.lo[k] > q.hi[k])
                q.lo[k] = q.hi[k] = 0.5 * (q.lo[k] + q.hi[k]);
            q.resting[k] = false;
            q.outside[k] = (q.on[k][0] && q.p[k] < q.lo[k]) || (q.on[k][1] && q.p[k] > q.hi[k]) ||
                           (q.lo[k] == q.hi[k]);
            if (walls && !q.outside[k])
                restIfPressed(q, k, balls.position(k, i));
        }
        updateBox(i);
    }
}

// An impact of two balls at t: the response on their velocities there, and
// their impacts planned again from their new paths.
void ImpactEvents::ballImpact(const BallState& balls, const Event& ev, double t, Response model, double e,
                              bool walls, std::vector<Contact>& met)
{
    Path& qa = m_path[static_cast<std::size_t>(ev.a)];
    Path& qb = m_path[static_cast<std::size_t>(ev.b)];
    moveTo(qa, t);
    moveTo(qb, t);
    const double ra = balls.radius[ev.a], rb = balls.radius[ev.b];
    const Vec2 d = qb.p - qa.p;
    const Vec2 normal = lineOfImpact(d, ra + rb, ev.a, ev.b);
    // The velocities the response sees. With the walls in this loop,
    // the path's own (what the exact wall model bounces too). Without,
    // the world's wall stage has already flipped the end velocity of a
    // ball that hit a wall, and its straight path from start to end
    // does not show it: the response then acts on the velocities the
    // balls really have (path + kick), and the path gets the same change.
    const Vec2 ka = walls ? Vec2::Zero() : qa.kick, kb = walls ? Vec2::Zero() : qb.kick;
    Vec2 va = qa.u + ka, vb = qb.u + kb;
    const double ec = m_ownE ? pairRestitution(m_ownE[ev.a], m_ownE[ev.b], e) : e;
    if (!respond(model, ec, d, normal, balls.inverseMass[ev.a], balls.inverseMass[ev.b], va, vb)) {
        // A naive model that leaves the pair approaching: it would
        // meet again at once, for ever. It is not followed further.
        const std::uint64_t key = pairKey(ev.a, ev.b);
        m_ignored.insert(std::lower_bound(m_ignored.begin(), m_ignored.end(), key), key);
        return;
    }
    qa.u = va - ka;
    qb.u = vb - kb;
    for (Path* q : {&qa, &qb}) {
        for (int k = 0; k < 2; ++k) { // pushed off (or into) the wall it rested on: moving again
            if (q->resting[k]) {
                q->resting[k] = false;
                q->a[k] = q->a0[k];
                q->kick[k] = q->kick0[k];
            }
        }
        ++q->version;
        q->moved = true;
    }
    ++m_counts.ballImpacts;
    met.push_back(Contact{ev.a, ev.b});
    updateBox(ev.a);
    updateBox(ev.b);
    planWall(ev.a, t);
    planWall(ev.b, t);
    planBall(ev.a, t, -1);
    planBall(ev.b, t, ev.a);
}

// An impact of a ball on a wall at t: it rests on the wall or bounces off it.
void ImpactEvents::wallImpact(const Event& ev, double t)
{
    Path& qa = m_path[static_cast<std::size_t>(ev.a)];
    const int code = -1 - ev.b, k = code / 2, side = code % 2;
    moveTo(qa, t);
    const double hitSpeed = qa.u[k];
    qa.p[k] = side ? qa.hi[k] : qa.lo[k];
    if (restsOnWall(ev.a, k, side, t, hitSpeed)) {
        qa.resting[k] = true;
        qa.u[k] = 0.0;
        qa.a[k] = 0.0;
        qa.kick[k] = 0.0;
        m_counts.wallHits += hitSpeed != 0.0 ? 1 : 0;
    } else {
        qa.u[k] = -wallE(ev.a) * hitSpeed;
        ++m_counts.wallHits;
    }
    ++qa.version;
    qa.moved = true;
    updateBox(ev.a);
    planWall(ev.a, t);
    planBall(ev.a, t, -1);
}

// The end of the step written into the balls.
void ImpactEvents::finishPaths(BallState& balls, const BoxSettings& box, const WallSettings& wallSettings, bool walls)
{
    // A ball without an impact keeps the integrator's state to the bit.
    const Matrix2X& x = balls.position;
    for (const int i : m_active) {
        Path& q = m_path[static_cast<std::size_t>(i)];
        Vec2 p = x.col(i), v = balls.velocity.col(i);
        if (q.moved) {
            const Vec2 before = x.col(i);
            p = positionAt(q, m_h);
            v = velocityAt(q, m_h) + q.kick;
            if (!walls) // the world's wall stage has acted: only keep the ball from being pushed through
                keepInsideWalls(before, p, balls.radius[i], box, wallSettings);
        }
        if (walls) {
            // Past a wall at the end (it started outside, the limit was
            // reached, or rounding): on the wall, moving away from it.
            for (int k = 0; k < 2; ++k) {
                for (int side = 0; side < 2; ++side) {
                    const double wall = side ? q.hi[k] : q.lo[k];
                    const double into = side ? 1.0 : -1.0;
                    if (q.on[k][side] && into * (p[k] - wall) > 0.0) {
                        p[k] = wall;
                        if (into * v[k] > 0.0)
                            v[k] = -wallE(i) * v[k];
                        ++m_counts.wallHits;
                    }
                }
            }
        }
        balls.position.col(i) = p;
        balls.velocity.col(i) = v;
    }
}

} // namespace forcelab::sim
