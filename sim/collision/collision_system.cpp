#include "collision_system.h"

#include "brute_force.h"
#include "halved.h"
#include "narrow_phase.h"
#include "positional_correction.h"
#include "response.h"
#include "time_of_impact.h"

#include <algorithm>

namespace forcelab::sim {

void CollisionSystem::findContacts(Detection method, bool swept, std::vector<Contact>& out, CollisionStats& stats)
{
    out.clear();
    const int n = m_input.size();
    auto run = [&](const auto& test) {
        switch (method) {
        case Detection::Brute:
            bruteForcePairs(n, test, out, stats);
            return; // already in (a, b) order
        case Detection::Halved:
            halvedPairs(n, test, out, stats);
            return; // already in (a, b) order
        case Detection::Sweep:
            m_sweep.findPairs(m_input, test, out, stats);
            break;
        case Detection::Grid:
            m_grid.findPairs(m_input, test, out, stats);
            break;
        }
        m_sorter.sort(out, n);
    };
    if (swept) {
        run(SweptTest{m_input.x0.data(), m_input.y0.data(), m_input.x.data(), m_input.y.data(), m_input.r.data()});
    } else {
        run(OverlapTest{m_input.x.data(), m_input.y.data(), m_input.r.data()});
    }
    stats.contacts += static_cast<std::int64_t>(out.size());
}

CollisionStats CollisionSystem::detect(const BallState& balls, Detection method, std::vector<Contact>& out)
{
    CollisionStats stats;
    m_input.loadStatic(balls);
    findContacts(method, false, out, stats);
    return stats;
}

CollisionStats CollisionSystem::detectMoving(const BallState& balls, const Matrix2X& startPositions,
                                             Detection method, std::vector<Contact>& out)
{
    CollisionStats stats;
    if (startPositions.cols() != balls.size())
        m_input.loadStatic(balls);
    else
        m_input.loadSwept(balls, startPositions);
    findContacts(method, startPositions.cols() == balls.size(), out, stats);
    return stats;
}

CollisionStats CollisionSystem::step(BallState& balls, const Matrix2X& startPositions,
                                     const CollisionSettings& settings, const BoxSettings& box,
                                     const WallSettings& walls, double dt)
{
    CollisionStats stats;
    const int n = balls.size();
    balls.colliding.assign(static_cast<std::size_t>(n), 0);
    if (settings.response == Response::None) {
        m_contacts.clear();
        return stats;
    }
    const bool continuous = settings.continuous && startPositions.cols() == n;
    if (continuous)
        m_input.loadSwept(balls, startPositions);
    else
        m_input.loadStatic(balls);
    findContacts(settings.detection, continuous, m_contacts, stats);

    for (const Contact& c : m_contacts) {
        balls.colliding[static_cast<std::size_t>(c.a)] = 1;
        balls.colliding[static_cast<std::size_t>(c.b)] = 1;
    }
    if (settings.response != Response::Flag && !m_contacts.empty())
        resolve(balls, continuous ? &startPositions : nullptr, settings, box, walls, dt);
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
    if (start)
        m_impact.assign(static_cast<std::size_t>(balls.size()), 0);
    const double e = settings.restitution;
    const Response model = settings.response;
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
                    separate(pa2, pb2, ra, rb, n, wa, wb, box, walls);
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
        if (separate(pa, pb, ra, rb, n, wa, wb, box, walls) > 0.0) {
            x.col(a) = pa;
            x.col(b) = pb;
        }
    }
}

} // namespace forcelab::sim
