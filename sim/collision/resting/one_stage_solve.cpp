// The one-stage resting-contact solve (one_stage_solve.h): warm start,
// velocity passes, bounces, the move and positional correction.

#include "sim/collision/resting/one_stage_solve.h"

#include "sim/collision/response/positional_correction.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {

RestingCounts OneStageSolve::solve(RestingRows& r, const SubStepContext& c, StageClock& clock,
                                   CollisionProfile& profile)
{
    const bool profiling = clock.on();
    m_passes = 0;
    warmStart(r);
    relax(r, c, profile, profiling);
    clock.lap(profile.velocity);
    bounce(r, c, profile, profiling);
    clock.lap(profile.restitution);
    moveBodies(r, c);
    clock.lap(profile.position);
    correctPositions(r, c);
    clock.lap(profile.correction);
    RestingCounts counts;
    counts.passes = m_passes;
    return counts;
}

// Stage 3. Last sub-step's impulse of every contact that is still there: a
// pile that rested then starts from the pushes that held it.
void OneStageSolve::warmStart(RestingRows& r)
{
    for (std::size_t k = 0; k < r.rowCount; ++k)
        if (r.impulse[k] > 0.0)
            applyPair(r.bodies.data(), r.pairRows[k], r.impulse[k]);
    for (const WallRow& row : r.wallRows)
        if (row.impulse > 0.0)
            wallSpeed(r.bodies.data(), row) -= row.side * row.w * row.impulse;
}

// Stage 4. Each contact's total impulse (never negative: balls push, they do
// not pull) is adjusted until the pair no longer approaches faster than it
// may: total = max(total − (v_n + allowed)·m_eff, 0). After the first pass a
// contact is solved again only if one of its balls changed speed by more
// than the tolerance since it was last solved (pass stamps per body); the
// passes stop when no ball changed by more than that.
void OneStageSolve::relax(RestingRows& r, const SubStepContext& c, CollisionProfile& profile, bool profiling)
{
    const double tolerance = c.solver.relaxTolerance * c.restingSpeed;
    const int passes = std::max(1, c.solver.velocityPasses);
    const PairRow* rows = r.pairRows.data();
    double* impulse = r.impulse.data();
    RestingBody* body = r.bodies.data();
    int made = 0;
    std::int64_t solves = 0;
    for (int pass = 0; pass < passes; ++pass) {
        bool moved = false;
        const int since = pass - 1;
        // Strip by strip (row_strips.h): each strip's rows in their order,
        // its own flag and count, combined in strip order afterwards.
        r.strips.run([&](int strip, int begin, int end) {
            bool stripMoved = false;
            std::int64_t stripSolves = 0;
            forEachInterleaved(begin, end, [&](std::size_t k) {
                const PairRow& row = rows[k];
                RestingBody& ba = body[row.a];
                RestingBody& bb = body[row.b];
                if (pass > 0 && ba.changed < since && bb.changed < since)
                    return;
                ++stripSolves;
                const double total = std::max(impulse[k] - (normalSpeed(body, row) + row.allowed) * row.mass, 0.0);
                const double j = total - impulse[k];
                impulse[k] = total;
                applyPair(body, row, j);
                const double dj = std::abs(j);
                if (dj * ba.w > tolerance) {
                    ba.changed = pass;
                    stripMoved = true;
                }
                if (dj * bb.w > tolerance) {
                    bb.changed = pass;
                    stripMoved = true;
                }
            });
            r.stripMoved[static_cast<std::size_t>(strip)] = stripMoved;
            r.stripSolves[static_cast<std::size_t>(strip)] = stripSolves;
        });
        for (std::size_t s = 0; s < r.strips.stripCount(); ++s) {
            moved = moved || r.stripMoved[s];
            solves += r.stripSolves[s];
            r.stripMoved[s] = 0;
            r.stripSolves[s] = 0;
        }
        for (WallRow& row : r.wallRows) {
            RestingBody& bw = body[row.body];
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
    m_passes += made;
    if (profiling) {
        profile.rows += static_cast<std::int64_t>(r.rowCount);
        profile.solves += solves;
    }
}

// Stage 5. A pair that hit faster than the resting speed separates at e times
// the speed it hit with; slower ones stay at rest (the threshold); a ball
// that hit a wall faster than that leaves it at e_w times its speed. These
// become the rows' targets and the passes run again over all rows, so the
// other contacts hold while the bounces are made: a ball dropped on a
// resting pile leaves it as from a floor, instead of pushing the ball it hit
// into the pile.
void OneStageSolve::bounce(RestingRows& r, const SubStepContext& c, CollisionProfile& profile, bool profiling)
{
    bool any = false;
    for (std::size_t k = 0; k < r.rowCount; ++k) {
        const double vn0 = r.vn0[k];
        if (!(-vn0 > c.restingSpeed) || !(r.impulse[k] > 0.0))
            continue;
        r.pairRows[k].allowed = static_cast<float>(r.restitutionOf(r.pairRows[k], c) * vn0); // v_n ≥ e·|v_n0|
        any = true;
    }
    for (WallRow& row : r.wallRows) {
        if (!(row.into0 > c.restingSpeed) || !(row.impulse > 0.0) || row.allowed != 0.0)
            continue;
        row.allowed = -r.restitutionOf(row, c) * row.into0; // leaves at e_w times the speed it came with
        any = true;
    }
    if (any)
        relax(r, c, profile, profiling);
    // The passes skip a row whose balls changed little; one more pass over the
    // walls leaves no ball moving into a wall faster than its row allows (a
    // wall never pushes a ball into another).
    for (WallRow& row : r.wallRows) {
        double& vk = wallSpeed(r.bodies.data(), row);
        const double total = std::max(row.impulse + (row.side * vk - row.allowed) / row.w, 0.0);
        vk -= row.side * row.w * (total - row.impulse);
        row.impulse = total;
    }
}

// Stage 6. The integrator moved the balls with their velocities before the
// contacts acted; move them as if the contact impulses had acted at the start
// of the sub-step (what a solver between the velocity and the position
// update does): by (v − v_before)·h, without crossing a wall. The bodies
// only: the velocity of every other ball is what it was before the solve.
void OneStageSolve::moveBodies(RestingRows& r, const SubStepContext& c)
{
    for (int k = 0; k < r.bodyCount; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        BodyPosition& pk = r.bodyPositions[kk];
        moveWithinWalls(pk.x, pk.y, pk.r, (r.bodies[kk].v[0] - r.bodyVelocity0[2 * kk]) * c.h,
               (r.bodies[kk].v[1] - r.bodyVelocity0[2 * kk + 1]) * c.h, c);
    }
}

// Stage 7. Overlap up to slop · (smaller radius) is allowed; `correction` of
// the rest is removed per pass, shared as the inverse masses, positions
// only. Most rows rest within the slop or are speculative: a squared-distance
// test skips them without a square root.
void OneStageSolve::correctPositions(RestingRows& r, const SubStepContext& c)
{
    const WallCheck check{{{c.walls.left, c.walls.right}, {c.walls.top, c.walls.bottom}}, {c.box.width, c.box.height}};
    const PairRow* rows = r.pairRows.data();
    BodyPosition* position = r.bodyPositions.data();
    for (int pass = 0; pass < std::max(1, c.solver.positionPasses); ++pass) {
        r.strips.run([&](int, int begin, int end) {
            forEachInterleaved(begin, end, [&](std::size_t k) {
                const PairRow& row = rows[k];
                BodyPosition& A = position[row.a];
                BodyPosition& B = position[row.b];
                const double ra = A.r, rb = B.r;
                const double allowed = c.solver.slop * std::min(ra, rb);
                const double reachAllowed = ra + rb - allowed; // centres closer than this get a push
                const double dx = B.x - A.x, dy = B.y - A.y;
                if (!(dx * dx + dy * dy < reachAllowed * reachAllowed) || !(reachAllowed > 0.0))
                    return;
                Vec2 pa(A.x, A.y), pb(B.x, B.y);
                const double depth = ra + rb - std::sqrt(dx * dx + dy * dy);
                if (!(depth > allowed))
                    return;
                const double push = c.solver.correction * (depth - allowed);
                const Vec2 nrm(row.nx, row.ny);
                const double wa = A.w, wb = B.w;
                const double moveA = push * (wa / (wa + wb));
                const Vec2 qa = pa - moveA * nrm, qb = pb + (push - moveA) * nrm;
                if (check.inside(qa.x(), qa.y(), ra) && check.inside(qb.x(), qb.y(), rb)) {
                    pa = qa;
                    pb = qb;
                } else {
                    pushApart(pa, pb, {ra, rb, nrm, wa, wb}, push, c.box, c.walls); // stops at the walls
                }
                A.x = pa.x();
                A.y = pa.y();
                B.x = pb.x();
                B.y = pb.y();
            });
        });
    }
}

} // namespace forcelab::sim
