#include "collision_system.h"

#include "brute_force.h"
#include "halved.h"
#include "narrow_phase.h"
#include "positional_correction.h"
#include "response.h"
#include "time_of_impact.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {
namespace {

// The pass over all contacts for one response model (a template, so the
// model's few lines are inlined into the loop). Same maths as the general
// path in resolve(): normal from the detection-time positions, response,
// then positional correction on the current positions.
template <Response Model>
void resolveContacts(const std::vector<Contact>& contacts, const Matrix2X& detected, BallState& balls, double e,
                     const BoxSettings& box, const WallSettings& walls)
{
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    const double* p = detected.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    const WallCheck check{{{walls.left, walls.right}, {walls.top, walls.bottom}}, {box.width, box.height}};
    for (const Contact& c : contacts) {
        const std::size_t a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
        const double ra = radius[a], rb = radius[b], s = ra + rb;
        const double wa = inverseMass[a], wb = inverseMass[b];
        const Vec2 d(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]);
        const double len = d.norm();
        const Vec2 n = (len > 1e-12 * s && std::isfinite(len)) ? Vec2(d / len) : lineOfImpact(d, s, c.a, c.b);
        Vec2 va(v[2 * a], v[2 * a + 1]), vb(v[2 * b], v[2 * b + 1]);
        bool changed = false;
        if constexpr (Model == Response::Reverse1D)
            changed = reverse1D(d, va, vb);
        else if constexpr (Model == Response::Elastic1D)
            changed = elastic1D(e, d, wa, wb, va, vb);
        else if constexpr (Model == Response::Axis2D)
            changed = axis2D(e, d, wa, wb, va, vb);
        else
            changed = impulse2D(e, n, wa, wb, va, vb);
        if (changed) {
            v[2 * a] = va.x();
            v[2 * a + 1] = va.y();
            v[2 * b] = vb.x();
            v[2 * b + 1] = vb.y();
        }
        Vec2 pa(x[2 * a], x[2 * a + 1]), pb(x[2 * b], x[2 * b + 1]);
        const double depth = s - (pb - pa).norm();
        if (!(depth > 0.0))
            continue;
        const double w = wa + wb;
        const double shareA = (w > 0.0 && std::isfinite(w)) ? wa / w : 0.5;
        const double moveA = depth * shareA;
        const Vec2 qa = pa - moveA * n, qb = pb + (depth - moveA) * n;
        if (check.inside(qa.x(), qa.y(), ra) && check.inside(qb.x(), qb.y(), rb)) {
            pa = qa;
            pb = qb;
        } else {
            separate(pa, pb, {ra, rb, n, wa, wb}, box, walls); // stops at the walls
        }
        x[2 * a] = pa.x();
        x[2 * a + 1] = pa.y();
        x[2 * b] = pb.x();
        x[2 * b + 1] = pb.y();
    }
}

} // namespace

void CollisionSystem::allowSleep(bool on)
{
    if (!on)
        m_sleep.wakeAll();
    m_sleepAllowed = on;
}

SubStepContext CollisionSystem::subStep(const CollisionSettings& settings, const BoxSettings& box,
                                        const WallSettings& walls, double h, double restingSpeed,
                                        const Vec2& gravity) const
{
    SubStepContext c;
    c.h = h;
    c.inverseH = 1.0 / h;
    c.box = box;
    c.walls = walls;
    c.restitution = settings.restitution;
    c.restingSpeed = restingSpeed;
    c.gravity = gravity.norm();
    c.gravityX = gravity.x();
    c.gravityY = gravity.y();
    c.solver = m_solver;
    return c;
}

void CollisionSystem::findContacts(Detection method, bool swept, std::vector<Contact>& out, CollisionStats& stats,
                                   StageClock& clock)
{
    out.clear();
    const int n = m_input.size();
    auto run = [&](const auto& test) {
        switch (method) {
        case Detection::Brute:
            bruteForcePairs(n, test, out, stats);
            clock.lap(m_profile.pairs);
            return; // already in (a, b) order
        case Detection::Halved:
            halvedPairs(n, test, out, stats);
            clock.lap(m_profile.pairs);
            return; // already in (a, b) order
        case Detection::Sweep:
            m_sweep.findPairs(m_input, test, out, stats, clock, m_profile);
            break;
        case Detection::Grid:
            m_grid.findPairs(m_input, test, out, stats, clock, m_profile);
            break;
        }
        m_sorter.sort(out, n);
        clock.lap(m_profile.contactSort);
    };
    if (swept) {
        run(SweptTest{BallArrays{m_input.x.data(), m_input.y.data(), m_input.r.data(), m_input.x0.data(),
                                 m_input.y0.data()}});
    } else {
        run(OverlapTest{BallArrays{m_input.x.data(), m_input.y.data(), m_input.r.data()}});
    }
    stats.contacts += static_cast<std::int64_t>(out.size());
}

CollisionStats CollisionSystem::detect(const BallState& balls, Detection method, std::vector<Contact>& out)
{
    CollisionStats stats;
    StageClock clock(m_profiling);
    m_input.loadStatic(balls);
    clock.lap(m_profile.load);
    findContacts(method, false, out, stats, clock);
    return stats;
}

CollisionStats CollisionSystem::detectMoving(const BallState& balls, const Matrix2X& startPositions,
                                             Detection method, std::vector<Contact>& out)
{
    CollisionStats stats;
    StageClock clock(m_profiling);
    if (startPositions.cols() != balls.size())
        m_input.loadStatic(balls);
    else
        m_input.loadSwept(balls, startPositions);
    clock.lap(m_profile.load);
    findContacts(method, startPositions.cols() == balls.size(), out, stats, clock);
    return stats;
}

CollisionStats CollisionSystem::step(BallState& balls, const Matrix2X& startPositions,
                                     const CollisionSettings& settings, const BoxSettings& box,
                                     const WallSettings& walls, double dt, const Vec2& gravity)
{
    CollisionStats stats;
    m_lastPasses = 0;
    m_lastBounceRows = 0;
    m_lastBounced = false;
    StageClock clock(m_profiling);
    if (m_profiling)
        ++m_profile.calls;
    const int n = balls.size();
    balls.colliding.assign(static_cast<std::size_t>(n), 0);
    if (settings.response == Response::None) {
        m_contacts.clear();
        return stats;
    }
    const bool continuous = settings.continuous && startPositions.cols() == n;
    const double g = gravity.norm();
    const double restingSpeed = m_solver.restingFactor * g * dt;
    const bool resting = settings.resting && settings.response == Response::Impulse2D && !continuous &&
                         restingSpeed > 0.0 && std::isfinite(restingSpeed);
    // Sleeping needs the staged solve with speculative contacts; any other
    // step wakes every ball.
    const bool sleeping = resting && m_solver.speculative > 0.0 && m_solver.stages > 1 && m_sleepAllowed &&
                          m_solver.sleepTime > 0.0;
    if (!sleeping)
        m_sleep.wakeAll();
    if (resting && m_solver.speculative > 0.0) {
        if (sleeping) {
            m_sleep.hold(balls); // the sleepers back where they sleep, before anything reads them
            clock.lap(m_profile.sleep);
        }
        // Speculative contacts: every ball grown by the distance one sub-step
        // can bring it closer to a neighbour, |v − u|·h + |g|·h² with u the
        // mean velocity around it, at most `speculative` of its radius
        // (speculative_margin.h). The grown pairs include every overlapping
        // pair (a sum of larger numbers is never smaller in floating point),
        // and all four detectors find the same grown pairs in the same order.
        m_margin.compute(balls, dt, g * dt * dt, m_solver.speculative, m_grow);
        m_input.loadStatic(balls, m_grow.data());
        clock.lap(m_profile.load);
        findContacts(settings.detection, false, m_speculative, stats, clock);
        const double stillSpeed = m_solver.stillShare * restingSpeed;
        if (sleeping) {
            m_sleep.wakeNear(balls, m_speculative, gravity * dt, dt, stillSpeed, m_solver.wakeShare * restingSpeed,
                             m_solver.wakeLayers);
            clock.lap(m_profile.sleep);
        }
        // The solver puts the pairs that overlap now back into m_contacts
        // (what contacts(), the flags and the counters report) as it builds
        // its rows.
        m_resting.solve(balls, subStep(settings, box, walls, dt, restingSpeed, gravity), m_speculative, &m_contacts, clock,
                        m_profile, sleeping ? m_sleep.asleep() : nullptr);
        if (sleeping) {
            m_sleep.settle(balls, m_speculative, m_resting.held(), dt, stillSpeed, m_solver.sleepTime);
            clock.lap(m_profile.sleep);
        }
        m_lastPasses = m_resting.lastPasses();
        m_lastBounceRows = m_resting.lastBounceRows();
        m_lastBounced = m_resting.lastBounced();
        stats.contacts = static_cast<std::int64_t>(m_contacts.size());
        if (m_profiling)
            m_profile.passes += m_lastPasses;
        return stats;
    } else {
        if (continuous)
            m_input.loadSwept(balls, startPositions);
        else
            m_input.loadStatic(balls);
        clock.lap(m_profile.load);
        findContacts(settings.detection, continuous, m_contacts, stats, clock);
    }

    for (const Contact& c : m_contacts) {
        balls.colliding[static_cast<std::size_t>(c.a)] = 1;
        balls.colliding[static_cast<std::size_t>(c.b)] = 1;
    }
    clock.lap(m_profile.build);
    if (settings.response == Response::Flag) {
        m_resting.forget();
        return stats;
    }
    if (resting) {
        m_resting.solve(balls, subStep(settings, box, walls, dt, restingSpeed, gravity), m_contacts, nullptr, clock,
                        m_profile);
        m_lastPasses = m_resting.lastPasses();
        m_lastBounceRows = m_resting.lastBounceRows();
        m_lastBounced = m_resting.lastBounced();
        if (m_profiling)
            m_profile.passes += m_lastPasses;
        return stats;
    }
    m_resting.forget(); // no resting solve: nothing to warm-start from next time
    if (!m_contacts.empty())
        resolve(balls, continuous ? &startPositions : nullptr, settings, box, walls, dt);
    clock.lap(m_profile.correction);
    return stats;
}

void CollisionSystem::resolve(BallState& balls, const Matrix2X* start, const CollisionSettings& settings,
                              const BoxSettings& box, const WallSettings& walls, double dt)
{
    // Normals come from the positions at detection, not from positions already
    // moved by earlier pairs of this pass: the line of impact of a pair does not
    // depend on the order, and balls stacked on one point get the spread-out
    // fallback directions of lineOfImpact for every pair.
    m_detected = balls.position;
    const double e = settings.restitution;
    const Response model = settings.response;
    if (!start) {
        switch (model) {
        case Response::None:
        case Response::Flag:
            return;
        case Response::Reverse1D:
            return resolveContacts<Response::Reverse1D>(m_contacts, m_detected, balls, e, box, walls);
        case Response::Elastic1D:
            return resolveContacts<Response::Elastic1D>(m_contacts, m_detected, balls, e, box, walls);
        case Response::Axis2D:
            return resolveContacts<Response::Axis2D>(m_contacts, m_detected, balls, e, box, walls);
        case Response::Impulse2D:
            return resolveContacts<Response::Impulse2D>(m_contacts, m_detected, balls, e, box, walls);
        }
        return;
    }
    m_impact.assign(static_cast<std::size_t>(balls.size()), 0);
    auto& x = balls.position;
    auto& v = balls.velocity;

    for (const Contact& c : m_contacts) {
        const int a = c.a, b = c.b;
        const double ra = balls.radius[a], rb = balls.radius[b];
        const double wa = balls.inverseMass[a], wb = balls.inverseMass[b];
        Vec2 va = v.col(a), vb = v.col(b);

        if (start && !m_impact[static_cast<std::size_t>(a)] && !m_impact[static_cast<std::size_t>(b)]) {
            // Continuous: did they meet inside the step? Rewind to that moment.
            const Vec2 sa = start->col(a), sb = start->col(b);
            const Vec2 ea = m_detected.col(a), eb = m_detected.col(b);
            const Vec2 d0 = sb - sa;
            const Vec2 dd = (eb - sb) - (ea - sa);
            const double t = timeOfImpact(d0.x(), d0.y(), dd.x(), dd.y(), ra + rb);
            if (t > 0.0) {
                const Vec2 pa = sa + t * (ea - sa), pb = sb + t * (eb - sb);
                const Vec2 d = pb - pa;
                const Vec2 n = lineOfImpact(d, ra + rb, a, b);
                if (respond(model, e, d, n, wa, wb, va, vb)) {
                    // Finish the step from the point of impact on the new velocities.
                    Vec2 qa = pa + ((1.0 - t) * dt) * va, qb = pb + ((1.0 - t) * dt) * vb;
                    keepInsideWalls(pa, qa, ra, box, walls);
                    keepInsideWalls(pb, qb, rb, box, walls);
                    x.col(a) = qa;
                    x.col(b) = qb;
                    v.col(a) = va;
                    v.col(b) = vb;
                    m_impact[static_cast<std::size_t>(a)] = 1;
                    m_impact[static_cast<std::size_t>(b)] = 1;
                    Vec2 pa2 = x.col(a), pb2 = x.col(b);
                    separate(pa2, pb2, {ra, rb, n, wa, wb}, box, walls);
                    x.col(a) = pa2;
                    x.col(b) = pb2;
                    continue;
                }
            }
        }

        const Vec2 d = m_detected.col(b) - m_detected.col(a);
        const Vec2 n = lineOfImpact(d, ra + rb, a, b);
        if (respond(model, e, d, n, wa, wb, va, vb)) {
            v.col(a) = va;
            v.col(b) = vb;
        }
        Vec2 pa = x.col(a), pb = x.col(b);
        if (separate(pa, pb, {ra, rb, n, wa, wb}, box, walls) > 0.0) {
            x.col(a) = pa;
            x.col(b) = pb;
        }
    }
}

} // namespace forcelab::sim
