// The rows and bodies of a resting-contact solve (resting_rows.h): stages
// 0-2 that build them, the strip order, and the write-back to the balls.

#include "sim/collision/resting/resting_rows.h"

#include "sim/collision/narrow_phase.h"
#include "sim/collision/response/positional_correction.h"
#include "sim/collision/response/response.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace forcelab::sim {
namespace {

// f(run) for run = 0 .. runs − 1: on this thread for one run, else on every core.
template <class F>
void forEachRun(std::size_t runs, F&& f)
{
    if (runs == 1)
        f(std::size_t{0});
    else
        oneapi::tbb::parallel_for(std::size_t{0}, runs, f);
}

// (a, b) order, the order of the contacts and of last sub-step's pairs.
bool before(const Contact& p, const Contact& q)
{
    return p.a < q.a || (p.a == q.a && p.b < q.b);
}

} // namespace

void RestingRows::build(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                        std::vector<Contact>* touching, StageClock& clock, CollisionProfile& profile,
                        const unsigned char* asleep)
{
    m_asleep = asleep;
    m_ownRestitution = c.ownRestitution;
    m_startShift[0] = c.startLag * c.gravityX * c.h * c.h;
    m_startShift[1] = c.startLag * c.gravityY * c.h * c.h;
    prepare(balls.size());
    takeBackWallBounces(balls, c);
    buildPairRows(balls, c, pairs, touching);
    clock.lap(profile.build);
    buildWallRows(balls, c);
    static_assert(sizeof(BodyPosition) == 4 * sizeof(double));
    strips.build(&bodyPositions.data()->x, rowCount,
                 [this](std::size_t k) { return 4 * static_cast<std::size_t>(pairRows[k].a); },
                 [this](std::size_t k) { return 4 * static_cast<std::size_t>(pairRows[k].b); });
    sortRowsByStrip();
    stripMoved.resize(strips.stripCount());
    stripSolves.resize(strips.stripCount());
    clock.lap(profile.wallScan);
}

void moveWithinWalls(double& px, double& py, double r, double dx, double dy, const SubStepContext& c)
{
    if (dx == 0.0 && dy == 0.0)
        return;
    const Vec2 p(px, py);
    Vec2 q(p.x() + dx, p.y() + dy);
    keepInsideWalls(p, q, r, c.box, c.walls);
    px = q.x();
    py = q.y();
}

// The rows, their impulses and approach speeds moved into strip order
// (row_strips.h), so the rows of a strip are read side by side.
void RestingRows::sortRowsByStrip()
{
    const std::vector<int>& order = strips.order();
    if (m_spareRows.size() < rowCount) // the arrays only grow
        m_spareRows.resize(rowCount);
    for (auto* values : {&m_spareImpulse, &m_spareVn0})
        if (values->size() < rowCount)
            values->resize(rowCount);
    for (std::size_t i = 0; i < rowCount; ++i) {
        const auto k = static_cast<std::size_t>(order[i]);
        m_spareRows[i] = pairRows[k];
        m_spareImpulse[i] = impulse[k];
        m_spareVn0[i] = vn0[k];
    }
    pairRows.swap(m_spareRows);
    impulse.swap(m_spareImpulse);
    vn0.swap(m_spareVn0);
}

// The impulses back in (a, b) order, beside m_rowBalls, for the next
// sub-step's warm-start merge.
void RestingRows::restoreRowOrder()
{
    const std::vector<int>& order = strips.order();
    if (m_spareImpulse.size() < rowCount)
        m_spareImpulse.resize(rowCount);
    for (std::size_t i = 0; i < rowCount; ++i)
        m_spareImpulse[static_cast<std::size_t>(order[i])] = impulse[i];
    impulse.swap(m_spareImpulse);
}

void RestingRows::prepare(int n)
{
    const auto size = static_cast<std::size_t>(n);
    if (m_warmCount != n) { // another set of balls: last sub-step's impulses mean nothing
        rowCount = 0;
        wallRows.clear();
        m_dormantBalls.clear();
        m_dormantImpulse.clear();
        m_warmCount = n;
    }
    if (bodyOf.size() != size)
        bodyOf.assign(size, -1);
    if (bodies.size() < size) {
        bodies.resize(size);
        bodyPositions.resize(size);
        bodyVelocity0.resize(2 * size);
        bodyShift.resize(2 * size);
        bodyRestitution.resize(size);
    }
    bodyCount = 0;
}

// The body of ball i, gathered from the balls the first time a row names it
// (its lines are in cache then): the velocity the passes change and the one
// before, the position and radius.
int RestingRows::bodyFor(std::size_t i, const BallState& balls)
{
    int k = bodyOf[i];
    if (k >= 0)
        return k;
    k = bodyCount++;
    bodyOf[i] = k;
    const double* v = balls.velocity.data();
    const double* x = balls.position.data();
    const auto kk = static_cast<std::size_t>(k);
    // A sleeper is at rest and cannot be moved: inverse mass 0.
    const bool sleeps = m_asleep && m_asleep[i];
    const double w = sleeps ? 0.0 : balls.inverseMass[static_cast<Eigen::Index>(i)];
    bodies[kk] = {{v[2 * i], v[2 * i + 1]}, w, -1};
    // A ball whose wall bounce stage 0 took back ended the integrator's step
    // on the wall: along that axis the position stage moves it by its new
    // velocity alone, from the wall.
    const unsigned char* back = &tookBack[2 * i];
    bodyVelocity0[2 * kk] = back[0] ? 0.0 : v[2 * i];
    bodyVelocity0[2 * kk + 1] = back[1] ? 0.0 : v[2 * i + 1];
    // What x − v·h misses its start by (sub_step_context.h); along an axis
    // whose wall bounce was taken back it starts on the wall instead, and a
    // pinned ball, which no force moved, starts where it is.
    if (m_ownRestitution)
        bodyRestitution[kk] = m_ownRestitution[i];
    const bool pinned = balls.pinned[i] != 0;
    for (int axis = 0; axis < 2; ++axis)
        bodyShift[2 * kk + static_cast<std::size_t>(axis)] = (back[axis] || pinned) ? 0.0 : m_startShift[axis];
    bodyPositions[kk] = {x[2 * i], x[2 * i + 1], balls.radius[static_cast<Eigen::Index>(i)], w};
    return k;
}

// Stage 0. A ball the wall stage has just put on an enabled wall (its gap
// is exactly 0, as clamp leaves it) and sent away at u met the wall at u/e_w.
// That bounce is taken back, so the rows see the ball as it came: its speed
// into the wall, and a start position one sub-step of that speed away. The
// solver makes the bounce again with the other contacts (relax stops the
// ball, the restitution stage sends it away at e_w times its speed if that
// was faster than v_rest). A ball under a pile then no longer hops at
// e_w·g·h every step and kicks the pile above it.
void RestingRows::takeBackWallBounces(BallState& balls, const SubStepContext& c)
{
    tookBack.assign(2 * static_cast<std::size_t>(balls.size()), 0);
    const double wallE = c.walls.restitution;
    const double* own = c.ownRestitution; // nullptr: wallE for every ball
    if (!own && !(wallE > 0.0))
        return;
    const bool on[2][2] = {{c.walls.left, c.walls.right}, {c.walls.top, c.walls.bottom}};
    const double size[2] = {c.box.width, c.box.height};
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    const double* radius = balls.radius.data();
    const bool staged = c.solver.stages > 1;
    for (int i = 0; i < balls.size(); ++i) {
        const double r = radius[i];
        const double ew = own ? effectiveRestitution(own[i], wallE) : wallE;
        if (!(ew > 0.0))
            continue; // a bounce at e_w = 0 cannot be taken back
        for (int k = 0; k < 2; ++k) {
            if (!(2.0 * r <= size[k]))
                continue;
            double& vk = v[2 * i + k];
            const double p = x[2 * i + k];
            // On a wall and leaving it first: few balls are, so the branch
            // is seldom taken and well predicted.
            if (!((on[k][0] && p - r == 0.0 && vk > 0.0) || (on[k][1] && size[k] - r - p == 0.0 && vk < 0.0)))
                continue;
            // The staged solve takes back only the small bounces of a ball
            // resting on a wall; a faster one stays the wall stage's, which
            // keeps a restitution-1 ball's energy exactly.
            if (!staged || std::abs(vk) <= ew * c.restingSpeed) {
                vk = -vk / ew;
                tookBack[2 * static_cast<std::size_t>(i) + static_cast<std::size_t>(k)] = 1;
            }
        }
    }
}

// Whether ball i may get a wall row (buildWallRows): not farther from every
// wall than the slop plus the distance gravity and its own speed move it in
// one sub-step. The quick test, on the largest margin.
static bool nearAWall(double px, double py, double r, double vx, double vy, const SubStepContext& c)
{
    const double far = c.solver.slop * r + c.gravity * c.h * c.h + (std::abs(vx) + std::abs(vy)) * c.h;
    return !(px - r >= far && c.box.width - r - px >= far && py - r >= far && c.box.height - r - py >= far);
}

inline double RestingRows::WarmStarts::of(const Contact& ct)
{
    const std::size_t oldCount = m_rows.rowCount, dormantCount = m_rows.m_dormantBalls.size();
    const Contact* oldBalls = m_rows.m_rowBalls.data();
    while (m_old < oldCount && before(oldBalls[m_old], ct))
        ++m_old;
    while (m_dormant < dormantCount && before(m_rows.m_dormantBalls[m_dormant], ct))
        ++m_dormant;
    double warm = (m_old < oldCount && oldBalls[m_old] == ct) ? m_rows.impulse[m_old] : 0.0;
    if (m_dormant < dormantCount && m_rows.m_dormantBalls[m_dormant] == ct)
        warm = m_rows.m_dormantImpulse[m_dormant];
    return warm;
}

// Puts the walk at the first of last sub-step's pairs not before `ct`, as if
// every pair before `ct` had been asked for (a run of pairs starts there).
inline void RestingRows::WarmStarts::skipTo(const Contact& ct)
{
    const Contact* oldBalls = m_rows.m_rowBalls.data();
    m_old = static_cast<std::size_t>(std::lower_bound(oldBalls, oldBalls + m_rows.rowCount, ct, before) - oldBalls);
    const std::vector<Contact>& dormant = m_rows.m_dormantBalls;
    m_dormant = static_cast<std::size_t>(std::lower_bound(dormant.begin(), dormant.end(), ct, before) - dormant.begin());
}

// The line of impact and the gap at the start of the sub-step: the
// integrator moved each ball by v·h before this stage, so the centres were
// d − (v_b − v_a)·h apart. A fast ball may already sit deep in (or beyond)
// the other at the end, where the direction means little.
inline RestingRows::PairStart RestingRows::startOf(const double* v, const Contact& ct, double dx, double dy,
                                                   double s, double warm, double wa, double wb,
                                                   const SubStepContext& c) const
{
    const auto a = static_cast<std::size_t>(ct.a), b = static_cast<std::size_t>(ct.b);
    const double dvx = v[2 * b] - v[2 * a], dvy = v[2 * b + 1] - v[2 * a + 1];
    const double sx = dx - dvx * c.h, sy = dy - dvy * c.h;
    const double len = std::sqrt(sx * sx + sy * sy);
    Vec2 nrm;
    if (len > 1e-12 * s && std::isfinite(len))
        nrm = Vec2(sx / len, sy / len);
    else
        nrm = lineOfImpact(Vec2(dx, dy), s, ct.a, ct.b);
    // The approach the pair ends the step with, less the speed gravity gave
    // a ball that contacts held in the last solve: those contacts take it
    // out again (a ball landing on a resting pile meets a ball at rest, not
    // one falling at g·h).
    const bool heldA = wasHeld(a), heldB = wasHeld(b);
    const double held = (heldB ? 1.0 : 0.0) - (heldA ? 1.0 : 0.0);
    const double approach = (dvx - held * c.gravityX * c.h) * nrm.x() + (dvy - held * c.gravityY * c.h) * nrm.y();
    return {nrm.x(), nrm.y(), len - s, approach, warm, wa, wb};
}

// The first loop of stage 1 over pairs [begin, end): each pair's kind and
// marks (m_pairKind, m_pairMark), the start geometry of a pair that rests or
// meets, and the pairs of two sleepers with their impulses, in pair order in
// `run`'s lists. It writes nothing else, so runs can go side by side.
void RestingRows::classifyPairs(const BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                                std::size_t begin, std::size_t end, PairRun& run)
{
    const double* x = balls.position.data();
    const double* v = balls.velocity.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    const bool islands = c.solver.stages > 1;
    unsigned char* kinds = m_pairKind.data();
    unsigned char* marks = m_pairMark.data();
    run.starts.clear();
    run.dormantBalls.clear();
    run.dormantImpulse.clear();
    WarmStarts warmStarts(*this);
    if (begin < end)
        warmStarts.skipTo(pairs[begin]);
    for (std::size_t p = begin; p < end; ++p) {
        const Contact ct = pairs[p];
        kinds[p] = kNone;
        // Ball b of a pair is anywhere in the arrays: its lines are asked
        // for a few pairs ahead, so their misses overlap.
        if (p + kPrefetchPairs < end) {
            const auto ahead = static_cast<std::size_t>(pairs[p + kPrefetchPairs].b);
            __builtin_prefetch(&x[2 * ahead]);
            __builtin_prefetch(&v[2 * ahead]);
            __builtin_prefetch(&radius[ahead]);
            __builtin_prefetch(&inverseMass[ahead]);
        }
        const auto a = static_cast<std::size_t>(ct.a), b = static_cast<std::size_t>(ct.b);
        const double s = radius[a] + radius[b];
        const double dx = x[2 * b] - x[2 * a], dy = x[2 * b + 1] - x[2 * a + 1];
        const bool overlap = dx * dx + dy * dy < s * s; // circlesOverlap, to the bit
        marks[p] = overlap ? kOverlaps : 0;
        double wa = inverseMass[a], wb = inverseMass[b];
        if (!detail::resolvable(wa, wb))
            continue;
        // Last sub-step's impulse of this pair, whether it was a row or a
        // pair of two sleepers.
        const double warm = warmStarts.of(ct);
        bool sleeper = false;
        if (m_asleep) {
            const bool sa = m_asleep[a], sb = m_asleep[b];
            if (sa && sb) { // two sleepers: no row, the impulse kept
                run.dormantBalls.push_back(ct);
                run.dormantImpulse.push_back(warm);
                continue;
            }
            sleeper = sa || sb;
            wa = sa ? 0.0 : wa;
            wb = sb ? 0.0 : wb;
        }
        const PairStart ps = startOf(v, ct, dx, dy, s, warm, wa, wb, c);
        if (!islands) {
            kinds[p] = kRow;
            run.starts.push_back(ps);
            continue;
        }
        // Its island needs the solver when the pair rests: it pushed in the
        // last sub-step, has a sleeper or a ball of infinite mass, or meets
        // a ball held in the last solve or slower than v_rest along its
        // line (under gravity alone, only an anchor: see `needy` below). A
        // ball near a wall anchors its island too. A pair meets when
        // it overlaps, or when its gap is less than it closes within the
        // sub-step plus what gravity closes in it if one ball is held
        // (|g|·h²: a column of balls standing at touching distance meets).
        // A pair that neither meets nor rests (a speculative pair) joins no
        // islands.
        const bool heldA = wasHeld(a), heldB = wasHeld(b);
        const bool meets = overlap || ps.gapStart + ps.approach * c.h < c.gravity * c.h * c.h;
        const bool infinite = !(wa > 0.0 && wb > 0.0) || !std::isfinite(wa + wb);
        const bool anchored = sleeper || infinite;
        const bool rests = anchored || warm > 0.0 ||
                           (meets && (heldA || heldB || std::abs(ps.approach) <= c.restingSpeed));
        // When every force gives every ball the same acceleration, a resting
        // pair joins its island but only an anchor (a sleeper, a ball of
        // infinite mass, a ball near a wall) makes the island need the
        // solver: without one the island falls as one, nothing presses its
        // balls together, and a slow pair in it is a slow impact that
        // bounces at e.
        const bool needy = c.sameForce ? anchored : rests;
        const bool wallA = nearAWall(x[2 * a], x[2 * a + 1], radius[a], v[2 * a], v[2 * a + 1], c);
        const bool wallB = nearAWall(x[2 * b], x[2 * b + 1], radius[b], v[2 * b], v[2 * b + 1], c);
        if (meets || rests) { // joins the islands; marks ball a's when its island needs the solver
            kinds[p] = meets ? kMeets : kRow;
            run.starts.push_back(ps);
            if (needy || wallA || wallB)
                marks[p] |= kNeedyA;
        } else {
            kinds[p] = kQuiet;
            if (wallA)
                marks[p] |= kNeedyA;
            if (wallB)
                marks[p] |= kNeedyB;
        }
    }
}

// Stage 1. One row per pair, in contact order ((a, b), like last sub-step's
// rows, so the impulses of pairs still in contact are found by a merge). The
// line of impact and the gap come from the centres at the start of the
// sub-step (startOf). A pair may close that gap and no more: its normal
// speed may not drop below −allowed (0 for pairs that overlap). The
// pairs that overlap now are copied to `touching` without a branch: each is
// written, and the count moves on by the result of the test.
//
// In the staged solve, rows are made only for the islands that need the
// resting solver (contact_islands.h): a first loop over the pairs finds
// each pair's kind and start geometry (classifyPairs), the islands are
// joined from the kinds in pair order, and a second loop makes the rows of
// the islands that need them and lists the meeting pairs of the free
// islands for their exact impulses (free_impacts.h).
void RestingRows::buildPairRows(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                                  std::vector<Contact>* touching)
{
    const double* x = balls.position.data();
    const double* v = balls.velocity.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    const std::size_t m = pairs.size();
    // The arrays only grow; the strip sort and its undoing swap some of them
    // with their spares, so each is checked on its own.
    if (m_spareRows.size() < m)
        m_spareRows.resize(m);
    if (m_spareBalls.size() < m)
        m_spareBalls.resize(m);
    for (auto* values : {&m_spareImpulse, &vn0})
        if (values->size() < m)
            values->resize(m);
    for (auto* perPair : {&m_pairKind, &m_pairMark})
        if (perPair->size() < m)
            perPair->resize(m);
    m_spareDormantBalls.clear();
    m_spareDormantImpulse.clear();
    freePairs.clear();
    if (touching && touching->size() < m)
        touching->resize(m);
    // Islands only in the staged solve; the one-stage solve makes every row.
    const bool islands = c.solver.stages > 1;
    if (islands)
        m_islands.reset(balls.size());
    // The first loop in runs of pairs, on every core when there are many
    // (each run writes only its own pairs' kinds and marks and its own
    // lists); then, on this thread and in pair order, the touching pairs and
    // the islands from the kinds and marks, and the runs' lists joined.
    const std::size_t runs = m >= kParallelPairs ? kPairRuns : 1;
    if (m_pairRuns.size() < runs)
        m_pairRuns.resize(runs);
    forEachRun(runs, [&](std::size_t run) {
        classifyPairs(balls, c, pairs, m * run / runs, m * (run + 1) / runs, m_pairRuns[run]);
    });
    std::size_t overlapping = 0;
    unsigned char* colliding = balls.colliding.data();
    for (std::size_t p = 0; p < m; ++p) {
        const Contact ct = pairs[p];
        const unsigned char mark = m_pairMark[p];
        if (touching) {
            const auto overlap = static_cast<unsigned char>(mark & kOverlaps);
            (*touching)[overlapping] = ct;
            overlapping += overlap;
            colliding[ct.a] |= overlap;
            colliding[ct.b] |= overlap;
        }
        if (!islands)
            continue;
        const unsigned char kind = m_pairKind[p];
        if (kind == kRow || kind == kMeets)
            m_islands.join(ct.a, ct.b);
        if (mark & kNeedyA)
            m_islands.markNeedy(ct.a);
        if (mark & kNeedyB)
            m_islands.markNeedy(ct.b);
    }
    if (touching)
        touching->resize(overlapping);
    if (runs == 1) {
        m_pairStart.swap(m_pairRuns[0].starts);
        m_spareDormantBalls.swap(m_pairRuns[0].dormantBalls);
        m_spareDormantImpulse.swap(m_pairRuns[0].dormantImpulse);
    } else {
        m_pairStart.clear();
        for (std::size_t run = 0; run < runs; ++run) {
            const PairRun& r = m_pairRuns[run];
            m_pairStart.insert(m_pairStart.end(), r.starts.begin(), r.starts.end());
            m_spareDormantBalls.insert(m_spareDormantBalls.end(), r.dormantBalls.begin(), r.dormantBalls.end());
            m_spareDormantImpulse.insert(m_spareDormantImpulse.end(), r.dormantImpulse.begin(), r.dormantImpulse.end());
        }
    }
    const unsigned char* kinds = m_pairKind.data();
    // A pair that does not meet, between an island that needs the solver
    // and one that does not, brings the other island into the solve: the
    // solver may push a ball of the first into it. One step only (the
    // marks are those of the first loop), so a gas next to a pile does not
    // join it ball by ball.
    if (islands) {
        m_attached.clear();
        for (std::size_t p = 0; p < m; ++p) {
            if (kinds[p] != kQuiet)
                continue;
            const Contact ct = pairs[p];
            const bool na = m_islands.needy(ct.a), nb = m_islands.needy(ct.b);
            if (na != nb)
                m_attached.push_back(na ? ct.b : ct.a);
        }
        for (const int i : m_attached)
            m_islands.markNeedy(i);
    }
    std::size_t count = 0, stored = 0;
    WarmStarts quietWarmStarts(*this); // for the pairs that do not meet but become rows
    for (std::size_t p = 0; p < m; ++p) {
        const unsigned char kind = kinds[p];
        if (kind == kNone)
            continue;
        const Contact ct = pairs[p];
        const auto a = static_cast<std::size_t>(ct.a), b = static_cast<std::size_t>(ct.b);
        PairStart ps;
        // A pair that does not meet is a row only between two balls whose
        // islands the solver takes (a speculative contact of a pile); the
        // pairs of free islands that meet get their exact impulses.
        if (kind == kQuiet) {
            if (!m_islands.needy(ct.a) || !m_islands.needy(ct.b))
                continue;
            // Neither ball sleeps nor has infinite mass (the pair would
            // rest): the first loop's geometry, found again.
            const double s = radius[a] + radius[b];
            const double dx = x[2 * b] - x[2 * a], dy = x[2 * b + 1] - x[2 * a + 1];
            ps = startOf(v, ct, dx, dy, s, quietWarmStarts.of(ct), inverseMass[a], inverseMass[b], c);
        } else {
            ps = m_pairStart[stored++];
            if (islands && !m_islands.needy(ct.a)) {
                if (kind == kMeets)
                    freePairs.push_back({ct.a, ct.b, ps.nx, ps.ny, ps.gapStart});
                continue;
            }
        }
        // A gap may close within the sub-step and no more: its normal speed
        // may not drop below −gap/h (0 for a pair that overlapped already).
        const double allowed = ps.gapStart > 0.0 ? ps.gapStart * c.inverseH : 0.0;
        const int ba = bodyFor(a, balls), bb = bodyFor(b, balls);
        m_spareRows[count] = {ba, bb, ps.nx, ps.ny, static_cast<float>(1.0 / (ps.wa + ps.wb)), static_cast<float>(allowed)};
        m_spareBalls[count] = ct;
        m_spareImpulse[count] = ps.warm;
        // A pair that pushed on each other in the last sub-step rests: only a
        // new contact bounces (a pile's pairs do not trade small bounces).
        vn0[count] = ps.warm > 0.0 ? 0.0 : ps.approach;
        ++count;
    }
    pairRows.swap(m_spareRows);
    m_rowBalls.swap(m_spareBalls);
    impulse.swap(m_spareImpulse);
    rowCount = count;
    m_dormantBalls.swap(m_spareDormantBalls);
    m_dormantImpulse.swap(m_spareDormantImpulse);
}

// Stage 2. One row for a ball on an enabled wall, or nearer to it than the
// slop plus the distance gravity moves a ball from rest in one sub-step (so
// it is caught before it hits, not after), plus what it moved away from the
// wall in this sub-step (a ball that just bounced off a wall can be pushed
// back into it by the balls above).
//
// How fast it may still move towards the wall: the position stage moves a
// body by (v − v_before)·h, so a ball whose speed towards the wall was u
// when the integrator moved it (negative: away) ends the sub-step
// gap − (v_wall − u)·h from the wall, where v_wall is its new speed towards
// it: it stays inside only for v_wall ≤ gap/h + u. A ball that is not
// near the end of its flight is never held back (a lone ball bounces as the
// wall model makes it); a ball whose bounce stage 0 took back starts on the
// wall (u = 0 for the position stage).
void RestingRows::buildWallRows(const BallState& balls, const SubStepContext& c)
{
    m_spareWalls.clear();
    const WallSettings& walls = c.walls;
    const bool on[2][2] = {{walls.left, walls.right}, {walls.top, walls.bottom}};
    const double size[2] = {c.box.width, c.box.height};
    const double reach = c.gravity * c.h * c.h;
    const double h = c.h;
    const double* x = balls.position.data();
    const double* v = balls.velocity.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    std::size_t old = 0;
    if (on[0][0] || on[0][1] || on[1][0] || on[1][1]) {
        auto add = [&](int i, int k, double side, double gap) {
            const int key = 4 * i + 2 * k + (side > 0.0 ? 1 : 0);
            while (old < wallRows.size() && wallRows[old].key < key)
                ++old;
            const double warm = (old < wallRows.size() && wallRows[old].key == key) ? wallRows[old].impulse : 0.0;
            const double w = inverseMass[i];
            const int bi = bodyFor(static_cast<std::size_t>(i), balls);
            const double into = side * v[2 * i + k];
            // The integrator has moved the ball by its speed into the wall
            // already (none for a ball whose bounce stage 0 took back: it
            // starts on the wall), so the speed that ends the sub-step on the
            // wall is the gap over h plus that speed, the same as a pair
            // row's gap at the start of the sub-step over h.
            const double moved = tookBack[2 * static_cast<std::size_t>(i) + static_cast<std::size_t>(k)] ? 0.0 : into;
            const double allowed = std::max(std::max(gap, 0.0) / h + moved, 0.0);
            m_spareWalls.push_back({key, bi, k, side, allowed, w, into, warm});
        };
        // Nothing near a wall gets a row: a quick test on the largest margin first.
        for (int i = 0; i < balls.size(); ++i) {
            const double r = radius[i], w = inverseMass[i];
            const double px = x[2 * i], py = x[2 * i + 1], vx = v[2 * i], vy = v[2 * i + 1];
            if (!nearAWall(px, py, r, vx, vy, c))
                continue;
            if (!(w > 0.0) || !std::isfinite(w) || (m_asleep && m_asleep[i]))
                continue; // a sleeper needs no wall: nothing moves it
            for (int k = 0; k < 2; ++k) {
                if (!(2.0 * r <= size[k]))
                    continue; // wider than the box: the wall stage keeps it in the middle
                const double p = x[2 * i + k], vk = v[2 * i + k];
                const double margin = c.solver.slop * r + reach;
                const double gapLow = p - r, gapHigh = size[k] - r - p;
                if (on[k][0] && gapLow < margin + std::max(vk, 0.0) * h)
                    add(i, k, -1.0, gapLow);
                if (on[k][1] && gapHigh < margin + std::max(-vk, 0.0) * h)
                    add(i, k, 1.0, gapHigh);
            }
        }
    }
    wallRows.swap(m_spareWalls);
}

// Stage 8. Velocities and positions back to the balls, in ball order; every
// ball is without a body again. A ball without a body moves by (v − v)·h:
// nowhere, or to NaN when its velocity is not finite, so a ball that blew up
// is seen by the world's blow-up check instead of standing still.
void RestingRows::writeBack(BallState& balls, const SubStepContext& c)
{
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    m_held.assign(static_cast<std::size_t>(balls.size()), 0);
    for (int i = 0; i < balls.size(); ++i) {
        const auto ii = static_cast<std::size_t>(i);
        const int k = bodyOf[ii];
        if (k >= 0) {
            const auto kk = static_cast<std::size_t>(k);
            m_held[ii] = bodies[kk].changed >= 0;
            v[2 * i] = bodies[kk].v[0];
            v[2 * i + 1] = bodies[kk].v[1];
            x[2 * i] = bodyPositions[kk].x;
            x[2 * i + 1] = bodyPositions[kk].y;
            bodyOf[ii] = -1;
            continue;
        }
        moveWithinWalls(x[2 * i], x[2 * i + 1], balls.radius[i], (v[2 * i] - v[2 * i]) * c.h, (v[2 * i + 1] - v[2 * i + 1]) * c.h,
               c);
    }
}

} // namespace forcelab::sim
