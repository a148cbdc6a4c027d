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

// Whether a ball of radius r at p is inside every enabled wall (the common
// case, where positional correction needs no wall handling).
struct WallCheck {
    bool on[2][2];
    double size[2];
    bool inside(double px, double py, double r) const
    {
        return (!on[0][0] || px >= r) && (!on[0][1] || px <= size[0] - r) && (!on[1][0] || py >= r) &&
               (!on[1][1] || py <= size[1] - r);
    }
};

// Calls f on every row, in four interleaved runs: rows k, k + q, k + 2q,
// k + 3q, then k + 1, ... (q = a quarter). Rows next to each other in (a, b)
// order share a ball, so each waits for the one before it; rows a quarter
// apart rarely do, and the processor works on four of them at once. The
// order is fixed by the row count alone, so a run stays repeatable.
template <class F>
void forEachInterleaved(std::size_t m, F&& f)
{
    const std::size_t q = (m + 3) / 4;
    std::size_t k = 0;
    for (; k + 3 * q < m; ++k) {
        f(k);
        f(k + q);
        f(k + 2 * q);
        f(k + 3 * q);
    }
    for (; k < q; ++k) {
        f(k);
        if (k + q < m)
            f(k + q);
        if (k + 2 * q < m)
            f(k + 2 * q);
    }
}

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
            separate(pa, pb, ra, rb, n, wa, wb, box, walls); // stops at the walls
        }
        x[2 * a] = pa.x();
        x[2 * a + 1] = pa.y();
        x[2 * b] = pb.x();
        x[2 * b + 1] = pb.y();
    }
}

} // namespace

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
    if (resting && m_solver.speculative > 0.0) {
        // Speculative contacts: every ball grown by the distance one sub-step
        // can bring it closer, |v|·h + |g|·h², at most `speculative` of its
        // radius. The grown pairs include every overlapping pair (a sum of
        // larger numbers is never smaller in floating point), and all four
        // detectors find the same grown pairs in the same order.
        const double* v = balls.velocity.data();
        const double* radius = balls.radius.data();
        const double fall = g * dt * dt;
        const double cap = m_solver.speculative;
        m_grow.resize(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            const double reach = std::sqrt(v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1]) * dt + fall;
            const double most = cap * radius[i];
            m_grow[static_cast<std::size_t>(i)] = reach < most ? reach : most; // NaN speed: the cap
        }
        m_input.loadStatic(balls, m_grow.data());
        clock.lap(m_profile.load);
        findContacts(settings.detection, false, m_speculative, stats, clock);
        // The solver puts the pairs that overlap now back into m_contacts
        // (what contacts(), the flags and the counters report) as it builds
        // its rows.
        solveResting(balls, settings.restitution, box, walls, dt, restingSpeed, g, m_speculative, clock);
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
        m_warmCount = -1;
        return stats;
    }
    if (resting) {
        solveResting(balls, settings.restitution, box, walls, dt, restingSpeed, g, m_contacts, clock);
        if (m_profiling)
            m_profile.passes += m_lastPasses;
        return stats;
    }
    m_warmCount = -1; // no resting solve: nothing to warm-start from next time
    if (!m_contacts.empty())
        resolve(balls, continuous ? &startPositions : nullptr, settings, box, walls, dt);
    clock.lap(m_profile.correction);
    return stats;
}

// The resting-contact solver (contact_solver.h): sequential impulses with
// accumulated, warm-started impulses over the ball–ball and ball–wall
// contacts, then positional correction with slop.
//
// The balls that take part are gathered into bodies (velocity, inverse mass,
// pass stamp: one 32-byte record each) in the order the rows first name them,
// and the rows refer to bodies. Every operation on a velocity is the one the
// solver made on the ball's column before, in the same order, so the results
// are the same to the bit; only the memory the passes touch is smaller and
// closer together.
void CollisionSystem::solveResting(BallState& balls, double e, const BoxSettings& box, const WallSettings& walls,
                                   double h, double restingSpeed, double gravity,
                                   const std::vector<Contact>& pairs, StageClock& clock)
{
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    const ContactSolverSettings& cs = m_solver;
    const int n = balls.size();
    if (m_warmCount != n) { // another set of balls: last sub-step's impulses mean nothing
        m_rowCount = 0;
        m_wallRows.clear();
        m_warmCount = n;
    }
    if (m_bodyOf.size() != static_cast<std::size_t>(n))
        m_bodyOf.assign(static_cast<std::size_t>(n), -1);
    if (m_bodies.size() < static_cast<std::size_t>(n)) {
        m_bodies.resize(static_cast<std::size_t>(n));
        m_bodyPositions.resize(static_cast<std::size_t>(n));
        m_bodyVelocity0.resize(2 * static_cast<std::size_t>(n));
    }
    int* bodyOf = m_bodyOf.data();
    Body* body = m_bodies.data();
    BodyPosition* position = m_bodyPositions.data();
    double* velocity0 = m_bodyVelocity0.data();
    int bodies = 0;
    // The body of ball i, gathered from the balls the first time it is named
    // (its lines are in cache then: the caller has just read them): the
    // velocity the passes change and the one before, the position and radius.
    auto bodyFor = [&](std::size_t i) {
        int k = bodyOf[i];
        if (k < 0) {
            k = bodies++;
            bodyOf[i] = k;
            body[k] = {{v[2 * i], v[2 * i + 1]}, inverseMass[i], -1};
            velocity0[2 * k] = v[2 * i];
            velocity0[2 * k + 1] = v[2 * i + 1];
            position[k] = {x[2 * i], x[2 * i + 1], radius[i], inverseMass[i]};
        }
        return k;
    };

    // Ball–ball rows, in contact order ((a, b), like last sub-step's rows, so
    // the impulses of pairs still in contact are found by a merge). The line
    // of impact comes from the positions at detection. A pair may close the
    // gap it had at the start of the sub-step, gap_end − v_n·h, and no more:
    // its normal speed may not drop below −allowed (0 for pairs that overlap).
    //
    // The rows are written by index into arrays that only grow, and the pairs
    // that overlap now are copied to m_contacts without a branch: each is
    // written, and the count moves on by the result of the test.
    const std::size_t m = pairs.size();
    if (m_spareRows.size() < m) {
        m_spareRows.resize(m);
        m_spareBalls.resize(m);
        m_spareImpulse.resize(m);
        m_vn0.resize(m);
    }
    std::size_t old = 0, count = 0, touching = 0;
    const std::size_t oldCount = m_rowCount;
    const Contact* oldBalls = m_rowBalls.data();
    const double* oldImpulse = m_impulse.data();
    PairRow* newRows = m_spareRows.data();
    Contact* newBalls = m_spareBalls.data();
    double* newImpulse = m_spareImpulse.data();
    double* vn0s = m_vn0.data();
    const double inverseH = 1.0 / h;
    const bool speculative = &pairs != &m_contacts;
    if (speculative && m_contacts.size() < m)
        m_contacts.resize(m);
    Contact* touchingOut = m_contacts.data();
    unsigned char* colliding = balls.colliding.data();
    for (std::size_t p = 0; p < m; ++p) {
        const Contact c = pairs[p];
        const auto a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
        const double s = radius[a] + radius[b];
        const double dx = x[2 * b] - x[2 * a], dy = x[2 * b + 1] - x[2 * a + 1];
        if (speculative) {
            const bool overlap = dx * dx + dy * dy < s * s; // circlesOverlap, to the bit
            touchingOut[touching] = c;
            touching += overlap;
            colliding[a] |= static_cast<unsigned char>(overlap);
            colliding[b] |= static_cast<unsigned char>(overlap);
        }
        const double wa = inverseMass[a], wb = inverseMass[b];
        if (!detail::resolvable(wa, wb))
            continue;
        const double len = std::sqrt(dx * dx + dy * dy);
        Vec2 nrm;
        if (len > 1e-12 * s && std::isfinite(len))
            nrm = Vec2(dx / len, dy / len);
        else
            nrm = lineOfImpact(Vec2(dx, dy), s, c.a, c.b);
        const double vn0 = (v[2 * b] - v[2 * a]) * nrm.x() + (v[2 * b + 1] - v[2 * a + 1]) * nrm.y();
        const double gapStart = (len - s) - vn0 * h;
        const double allowed = gapStart > 0.0 ? gapStart * inverseH : 0.0;
        while (old < oldCount && (oldBalls[old].a < c.a || (oldBalls[old].a == c.a && oldBalls[old].b < c.b)))
            ++old;
        const double warm =
            (old < oldCount && oldBalls[old].a == c.a && oldBalls[old].b == c.b) ? oldImpulse[old] : 0.0;
        const int ba = bodyFor(a), bb = bodyFor(b);
        newRows[count] = {ba, bb, nrm.x(), nrm.y(), static_cast<float>(1.0 / (wa + wb)), static_cast<float>(allowed)};
        newBalls[count] = c;
        newImpulse[count] = warm;
        vn0s[count] = vn0;
        ++count;
    }
    if (speculative)
        m_contacts.resize(touching);
    m_pairRows.swap(m_spareRows);
    m_rowBalls.swap(m_spareBalls);
    m_impulse.swap(m_spareImpulse);
    m_rowCount = count;
    const std::size_t rowCount = count;
    const PairRow* rows = m_pairRows.data();
    double* impulse = m_impulse.data();
    clock.lap(m_profile.build);

    // Ball–wall rows, in ball order: a ball on an enabled wall, or nearer to it
    // than the slop plus the distance gravity moves a ball from rest in one
    // sub-step (so it is caught before it hits, not after), plus what it moved
    // away from the wall in this sub-step (a ball that just bounced off a wall
    // can be pushed back into it by the balls above).
    //
    // How fast it may still move towards the wall: the gap over h, less the
    // speed it already leaves the wall with. The position update below moves
    // a body by (v − v_before)·h, so a ball the wall stage has just sent away
    // at speed u ends the sub-step gap − (v_wall + u)·h from the wall, where
    // v_wall is its new speed towards it: it stays inside only for
    // v_wall ≤ gap/h − u. With gap/h alone (the rule for a ball that comes
    // in), the exact wall model's floor ball hopped: the solver let it fall at
    // gap/h, the position update stopped it on the floor still moving into
    // it, and the next wall stage bounced it up again, every sub-step.
    m_spareWalls.clear();
    const bool on[2][2] = {{walls.left, walls.right}, {walls.top, walls.bottom}};
    const double size[2] = {box.width, box.height};
    const double reach = gravity * h * h;
    old = 0;
    if (on[0][0] || on[0][1] || on[1][0] || on[1][1]) {
        auto add = [&](int i, int k, double side, double gap) {
            const int key = 4 * i + 2 * k + (side > 0.0 ? 1 : 0);
            while (old < m_wallRows.size() && m_wallRows[old].key < key)
                ++old;
            const double warm = (old < m_wallRows.size() && m_wallRows[old].key == key) ? m_wallRows[old].impulse : 0.0;
            const double w = inverseMass[i];
            const int bi = bodyFor(static_cast<std::size_t>(i));
            const double into = side * v[2 * i + k];
            const double allowed = std::max(std::max(gap, 0.0) / h + std::min(into, 0.0), 0.0);
            m_spareWalls.push_back({key, bi, k, side, allowed, w, into, warm});
        };
        // Nothing near a wall gets a row: a quick test on the largest margin first.
        for (int i = 0; i < n; ++i) {
            const double r = radius[i], w = inverseMass[i];
            const double px = x[2 * i], py = x[2 * i + 1], vx = v[2 * i], vy = v[2 * i + 1];
            const double far = cs.slop * r + reach + (std::abs(vx) + std::abs(vy)) * h;
            if (px - r >= far && size[0] - r - px >= far && py - r >= far && size[1] - r - py >= far)
                continue;
            if (!(w > 0.0) || !std::isfinite(w))
                continue;
            for (int k = 0; k < 2; ++k) {
                if (!(2.0 * r <= size[k]))
                    continue; // wider than the box: the wall stage keeps it in the middle
                const double p = x[2 * i + k], vk = v[2 * i + k];
                const double margin = cs.slop * r + reach;
                const double gapLow = p - r, gapHigh = size[k] - r - p;
                if (on[k][0] && gapLow < margin + std::max(vk, 0.0) * h)
                    add(i, k, -1.0, gapLow);
                if (on[k][1] && gapHigh < margin + std::max(-vk, 0.0) * h)
                    add(i, k, 1.0, gapHigh);
            }
        }
    }
    m_wallRows.swap(m_spareWalls);
    clock.lap(m_profile.wallScan);

    auto applyPair = [&](const PairRow& row, double j) {
        Body& ba = body[row.a];
        Body& bb = body[row.b];
        const double ja = ba.w * j, jb = bb.w * j;
        ba.v[0] -= ja * row.nx;
        ba.v[1] -= ja * row.ny;
        bb.v[0] += jb * row.nx;
        bb.v[1] += jb * row.ny;
    };
    auto normalSpeed = [&](const PairRow& row) {
        const Body& ba = body[row.a];
        const Body& bb = body[row.b];
        return (bb.v[0] - ba.v[0]) * row.nx + (bb.v[1] - ba.v[1]) * row.ny;
    };
    auto wallSpeed = [&](const WallRow& row) -> double& { return body[row.body].v[row.axis]; };

    // Warm start: last sub-step's impulse of every contact that is still there.
    for (std::size_t k = 0; k < rowCount; ++k)
        if (impulse[k] > 0.0)
            applyPair(rows[k], impulse[k]);
    for (const WallRow& row : m_wallRows)
        if (row.impulse > 0.0)
            wallSpeed(row) -= row.side * row.w * row.impulse;

    // Relax passes: each contact's total impulse (never negative: balls push,
    // they do not pull) is adjusted until it no longer approaches faster than
    // it may. After the first pass a contact is solved again only if one of
    // its balls changed speed by more than the tolerance since it was last
    // solved (pass stamps per body); the others would get no impulse worth
    // having. The passes stop when no ball changed by more than that.
    const double tolerance = cs.relaxTolerance * restingSpeed;
    const int passes = std::max(1, cs.velocityPasses);
    int made = 0;
    std::int64_t solves = 0;
    for (int pass = 0; pass < passes; ++pass) {
        bool moved = false;
        const int since = pass - 1;
        forEachInterleaved(rowCount, [&](std::size_t k) {
            const PairRow& row = rows[k];
            Body& ba = body[row.a];
            Body& bb = body[row.b];
            if (pass > 0 && ba.changed < since && bb.changed < since)
                return;
            ++solves;
            const double total = std::max(impulse[k] - (normalSpeed(row) + row.allowed) * row.mass, 0.0);
            const double j = total - impulse[k];
            impulse[k] = total;
            applyPair(row, j);
            const double dj = std::abs(j);
            if (dj * ba.w > tolerance) {
                ba.changed = pass;
                moved = true;
            }
            if (dj * bb.w > tolerance) {
                bb.changed = pass;
                moved = true;
            }
        });
        for (WallRow& row : m_wallRows) {
            Body& bw = body[row.body];
            if (pass > 0 && bw.changed < since)
                continue;
            double& vk = bw.v[row.axis];
            const double into = row.side * vk;
            const double total = std::max(row.impulse + (into - row.allowed) / row.w, 0.0);
            const double j = total - row.impulse;
            row.impulse = total;
            vk -= row.side * row.w * j;
            if (std::abs(j) * row.w > tolerance) {
                bw.changed = pass;
                moved = true;
            }
        }
        ++made;
        if (!moved)
            break;
    }
    m_lastPasses = made;
    if (m_profiling) {
        m_profile.rows += static_cast<std::int64_t>(rowCount);
        m_profile.solves += solves;
    }
    clock.lap(m_profile.velocity);

    // Restitution: a pair that hit faster than the resting speed separates at
    // e times the speed it hit with; slower ones stay at rest (threshold).
    for (std::size_t k = 0; k < rowCount; ++k) {
        const double vn0 = m_vn0[k];
        if (!(-vn0 > restingSpeed) || !(impulse[k] > 0.0))
            continue;
        const PairRow& row = rows[k];
        const double total = std::max(impulse[k] + (-e * vn0 - normalSpeed(row)) * row.mass, 0.0);
        applyPair(row, total - impulse[k]);
        impulse[k] = total;
    }
    const double ew = walls.restitution;
    for (WallRow& row : m_wallRows) {
        if (!(row.into0 > restingSpeed) || !(row.impulse > 0.0) || row.allowed != 0.0)
            continue;
        double& vk = wallSpeed(row);
        const double total = std::max(row.impulse + (row.side * vk + ew * row.into0) / row.w, 0.0);
        vk -= row.side * row.w * (total - row.impulse);
        row.impulse = total;
    }
    // The bounces may have pushed a ball into a wall it rests on: one more
    // pass over the walls stops that (a wall never pushes a ball into another).
    for (WallRow& row : m_wallRows) {
        double& vk = wallSpeed(row);
        const double total = std::max(row.impulse + (row.side * vk - row.allowed) / row.w, 0.0);
        vk -= row.side * row.w * (total - row.impulse);
        row.impulse = total;
    }
    clock.lap(m_profile.restitution);

    // The integrator moved the balls with their velocities before the
    // contacts acted; move them as if the contact impulses had acted at the
    // start of the sub-step (what a solver that runs between the velocity and
    // the position update does), without crossing a wall. The bodies only:
    // the velocity of every other ball is what it was before the solve.
    auto moveBy = [&](double& px, double& py, double r, double dx, double dy) {
        if (dx == 0.0 && dy == 0.0)
            return;
        const Vec2 p(px, py);
        Vec2 q(p.x() + dx, p.y() + dy);
        keepInsideWalls(p, q, r, box, walls);
        px = q.x();
        py = q.y();
    };
    for (int k = 0; k < bodies; ++k) {
        BodyPosition& pk = position[k];
        moveBy(pk.x, pk.y, pk.r, (body[k].v[0] - velocity0[2 * k]) * h, (body[k].v[1] - velocity0[2 * k + 1]) * h);
    }
    clock.lap(m_profile.position);

    // Positional correction with slop, positions only. Most rows are resting
    // within the slop or speculative (not touching): a squared-distance test
    // skips them without a square root.
    const WallCheck check{{{walls.left, walls.right}, {walls.top, walls.bottom}}, {box.width, box.height}};
    for (int pass = 0; pass < std::max(1, cs.positionPasses); ++pass) {
        forEachInterleaved(rowCount, [&](std::size_t k) {
            const PairRow& row = rows[k];
            BodyPosition& A = position[row.a];
            BodyPosition& B = position[row.b];
            const double ra = A.r, rb = B.r;
            const double allowed = cs.slop * std::min(ra, rb);
            const double reachAllowed = ra + rb - allowed; // centres closer than this get a push
            const double dx = B.x - A.x, dy = B.y - A.y;
            if (!(dx * dx + dy * dy < reachAllowed * reachAllowed) || !(reachAllowed > 0.0))
                return;
            Vec2 pa(A.x, A.y), pb(B.x, B.y);
            const double depth = ra + rb - std::sqrt(dx * dx + dy * dy);
            if (!(depth > allowed))
                return;
            const double push = cs.correction * (depth - allowed);
            const Vec2 nrm(row.nx, row.ny);
            const double wa = A.w, wb = B.w;
            const double moveA = push * (wa / (wa + wb));
            const Vec2 qa = pa - moveA * nrm, qb = pb + (push - moveA) * nrm;
            if (check.inside(qa.x(), qa.y(), ra) && check.inside(qb.x(), qb.y(), rb)) {
                pa = qa;
                pb = qb;
            } else {
                pushApart(pa, pb, ra, rb, nrm, wa, wb, push, box, walls); // stops at the walls
            }
            A.x = pa.x();
            A.y = pa.y();
            B.x = pb.x();
            B.y = pb.y();
        });
    }
    clock.lap(m_profile.correction);

    // Velocities and positions back to the balls, in ball order; every ball
    // is without a body again. A ball without a body kept its velocity, so
    // (v − v)·h moves it: nowhere, or to NaN when its velocity is not finite,
    // as the position update always did.
    for (int i = 0; i < n; ++i) {
        const int k = bodyOf[i];
        if (k >= 0) {
            v[2 * i] = body[k].v[0];
            v[2 * i + 1] = body[k].v[1];
            x[2 * i] = position[k].x;
            x[2 * i + 1] = position[k].y;
            bodyOf[i] = -1;
            continue;
        }
        moveBy(x[2 * i], x[2 * i + 1], radius[i], (v[2 * i] - v[2 * i]) * h, (v[2 * i + 1] - v[2 * i + 1]) * h);
    }
    clock.lap(m_profile.position);
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
