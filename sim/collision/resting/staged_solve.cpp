// The staged solve of the resting solver (staged_solve.h, contact_solver.h
// point 6): the sub-step's contacts, found once, are solved in `stages`
// short stages of length hs = h / stages. Each stage gives the bodies their
// share of gravity, applies the contacts' impulses again (warm start),
// pushes overlaps apart through the velocities with soft contacts
// (soft_contact.h), moves the bodies, and takes the push out of the
// velocities again (relax). The bounces come last.

#include "sim/collision/resting/staged_solve.h"

#include "sim/collision/response/positional_correction.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace forcelab::sim {

// The soft contact's spring frequency is contactStiffness times the stage
// rate 1/hs, damped at dampingRatio of critical.
RestingCounts StagedSolve::solve(RestingRows& r, const SubStepContext& c)
{
    const ContactSolverSettings& settings = c.solver;
    const int stages = std::max(1, settings.stages);
    StageStep step;
    step.hs = c.h / stages;
    step.inverseHs = 1.0 / step.hs;
    step.soft = makeSoft(2.0 * std::numbers::pi * settings.contactStiffness * step.inverseHs, settings.dampingRatio,
                         step.hs);
    m_counts = RestingCounts{};
    m_rowGraph.clear(); // this solve's rows: built at its first region
    start(r, c);
    for (int stage = 0; stage < stages; ++stage)
        runStage(r, c, step, stage + 1 == stages);
    const bool any = markBounces(r, c);
    finalPasses(r, c, step, any);
    return m_counts;
}

// The bodies at the start of the sub-step: the integrator moved each by
// about v·h (a ball whose wall bounce stage 0 took back: from the wall;
// explicit Euler by g·h² less, sub_step_context.h) and gave it g·h of
// speed; both are taken back, and each stage gives g·hs again.
void StagedSolve::start(RestingRows& r, const SubStepContext& c)
{
    const auto bodies = static_cast<std::size_t>(r.bodyCount);
    if (m_bodyStart.size() < 2 * bodies) {
        m_bodyStart.resize(2 * bodies);
        m_stageVelocity.resize(2 * bodies);
    }
    // A ball the wall stage has just bounced (its new velocity would take it
    // back beyond the wall) starts where the wall stage left it along that
    // axis.
    const bool on[2][2] = {{c.walls.left, c.walls.right}, {c.walls.top, c.walls.bottom}};
    const double size[2] = {c.box.width, c.box.height};
    for (std::size_t k = 0; k < bodies; ++k) {
        BodyPosition& p = r.bodyPositions[k];
        double* at[2] = {&p.x, &p.y};
        for (int axis = 0; axis < 2; ++axis) {
            const std::size_t ka = 2 * k + static_cast<std::size_t>(axis);
            const double q = *at[axis] - r.bodyVelocity0[ka] * c.h + r.bodyShift[ka];
            const bool beyond = (on[axis][0] && q - p.r < 0.0) || (on[axis][1] && size[axis] - p.r - q < 0.0);
            if (!beyond)
                *at[axis] = q;
        }
        m_bodyStart[2 * k] = p.x;
        m_bodyStart[2 * k + 1] = p.y;
        if (r.bodies[k].w > 0.0) { // a sleeper (w = 0) was given nothing and gets nothing
            r.bodies[k].v[0] -= c.gravityX * c.h;
            r.bodies[k].v[1] -= c.gravityY * c.h;
        }
        r.bodies[k].changed = -1; // −1: no impulse has touched it yet
    }
    // Each row's line of impact and gap from its bodies' start positions (the
    // wall stage may have moved one ball of a pair back onto a wall).
    if (m_gap.size() < r.rowCount) {
        m_gap.resize(r.rowCount);
        m_gapNow.resize(r.rowCount);
    }
    for (std::size_t k = 0; k < r.rowCount; ++k) {
        PairRow& row = r.pairRows[k];
        const BodyPosition& A = r.bodyPositions[static_cast<std::size_t>(row.a)];
        const BodyPosition& B = r.bodyPositions[static_cast<std::size_t>(row.b)];
        const double dx = B.x - A.x, dy = B.y - A.y, reach = A.r + B.r;
        const double len = std::sqrt(dx * dx + dy * dy);
        if (len > 1e-12 * reach && std::isfinite(len)) {
            row.nx = dx / len;
            row.ny = dy / len;
        }
        // Nothing has moved yet, so the gap now is the gap at the start
        // (updateGaps would add an exact zero to a gap that is never −0).
        m_gap[k] = len - reach;
        m_gapNow[k] = m_gap[k];
    }
    m_pushed.assign(r.rowCount, 0);
    m_hitSpeed.assign(r.rowCount, 0.0);
    m_hitNoted.assign(r.rowCount, 0);
    m_stageHits.clear();
    // A wall row's `allowed` holds, until the bounces, the speed its ball
    // came at the wall when the row first pushed: −1 until then, −2 for a
    // row that pushed in the last sub-step already (a resting ball).
    for (WallRow& row : r.wallRows)
        row.allowed = row.impulse > 0.0 ? -2.0 : -1.0;
}

// One stage of length hs (`last`: the sub-step's last), steps 1-5.
void StagedSolve::runStage(RestingRows& r, const SubStepContext& c, const StageStep& step, bool last)
{
    const ContactSolverSettings& settings = c.solver;
    const auto bodies = static_cast<std::size_t>(r.bodyCount);
    const int impactPasses = std::max(0, settings.velocityPasses - std::max(1, settings.stagePasses));
    const double gx = c.gravityX * step.hs, gy = c.gravityY * step.hs;
    const int stagePasses = std::max(1, settings.stagePasses), relaxPasses = std::max(0, settings.relaxPasses);
    // 1. Gravity's share: dv = g·hs. The speeds then are the ones a
    //    new contact of this stage hits with.
    for (std::size_t k = 0; k < bodies; ++k) {
        const double share = r.bodies[k].w > 0.0 ? 1.0 : 0.0; // a sleeper stays at rest
        r.bodies[k].v[0] += share * gx;
        r.bodies[k].v[1] += share * gy;
        m_stageVelocity[2 * k] = r.bodies[k].v[0];
        m_stageVelocity[2 * k + 1] = r.bodies[k].v[1];
    }
    // 2. Warm start: every contact's impulse of the stage before (of the
    //    last sub-step at the first stage) applied again, since gravity
    //    has added the same speed again.
    r.strips.run([&](int, int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const double j = r.impulse[static_cast<std::size_t>(k)];
            if (j > 0.0) {
                const PairRow& row = r.pairRows[static_cast<std::size_t>(k)];
                applyPair(r.bodies.data(), row, j);
                r.bodies[static_cast<std::size_t>(row.a)].changed = 0;
                r.bodies[static_cast<std::size_t>(row.b)].changed = 0;
            }
        }
    });
    for (const WallRow& row : r.wallRows)
        if (row.impulse > 0.0) {
            wallSpeed(r.bodies.data(), row) -= row.side * row.w * row.impulse;
            r.bodies[static_cast<std::size_t>(row.body)].changed = 0;
        }
    // 3. Passes that stop approaches and push overlaps apart (soft).
    for (int pass = 0; pass < stagePasses; ++pass)
        stagePass(r, c, step, true, false, false);
    // 3b. A ball that hits the pile (a new contact, faster than the
    //     resting speed) pushes on it for the rest of the sub-step. The
    //     stage's passes carry that push a few balls down and are soft
    //     where balls overlap, so the pile yielded and the struck ball
    //     sank into it: a ball dropped 200 px on a pile with verlet rose
    //     46% of e²·h0. From the stage of the hit on, the rows within
    //     bounceLayers balls of it get velocityPasses − stagePasses more
    //     passes that hold the pile rigid (no soft push), as a bounce's
    //     region does at the end. When that region is half the pile or
    //     more (a landing pile), only a solve of at most impactRows rows
    //     gets them, over every row.
    for (std::size_t k = 0; k < r.rowCount; ++k)
        if (m_pushed[k] != 0 && !m_hitNoted[k]) {
            m_hitNoted[k] = 1;
            if (r.vn0[k] != 0.0 && -m_hitSpeed[k] > c.restingSpeed)
                m_stageHits.push_back(static_cast<int>(k));
        }
    if (!m_stageHits.empty() && impactPasses > 0) {
        const bool region = settings.bounceLayers > 0 && markBounceRegion(r, settings.bounceLayers, &m_stageHits);
        if (region || r.rowCount <= static_cast<std::size_t>(settings.impactRows)) {
            for (int pass = 0; pass < impactPasses; ++pass)
                stagePass(r, c, step, false, false, false, region ? &m_bounceRows : nullptr);
            m_counts.passes += impactPasses;
        }
    }
    // 4. The bodies move by their speeds, never through an enabled wall.
    for (std::size_t k = 0; k < bodies; ++k) {
        BodyPosition& p = r.bodyPositions[k];
        const Vec2 from(p.x, p.y);
        Vec2 to(p.x + r.bodies[k].v[0] * step.hs, p.y + r.bodies[k].v[1] * step.hs);
        keepInsideWalls(from, to, p.r, c.box, c.walls);
        p.x = to.x();
        p.y = to.y();
    }
    updateGaps(r);
    // 5. Relax: passes without the push, so the speed that pushed the
    //    overlaps apart does not stay in the bodies.
    for (int pass = 0; pass < relaxPasses; ++pass)
        stagePass(r, c, step, false, false, last);
    m_counts.passes += stagePasses + relaxPasses;
}

// 6. Bounces. A new contact (no impulse in the last sub-step) whose pair
// came together faster than the resting speed separates at e times
// the speed it hit with; a ball that came at a wall that fast leaves
// at e_w times its speed. The speed it hit with is the one in the
// stage where it first pushed: the speed at the end of the sub-step
// has up to g·h more in it, and a bounce at e·(v + g·h) gains energy
// for every v below e·g·h/(1 − e) (150 px/s at 60 Hz, e = 0.9), so
// slow bouncers would never settle. The other rows keep what relax
// asks, so the pile under a bouncing ball holds.
bool StagedSolve::markBounces(RestingRows& r, const SubStepContext& c)
{
    bool any = false;
    for (std::size_t k = 0; k < r.rowCount; ++k) {
        const double hit = std::max(m_hitSpeed[k], r.vn0[k]); // never faster than at the end
        if (r.vn0[k] != 0.0 && -hit > c.restingSpeed && m_pushed[k]) {
            r.pairRows[k].allowed = static_cast<float>(r.restitutionOf(r.pairRows[k], c) * hit); // v_n ≥ e·|v_hit|
            m_pushed[k] = 2;
            any = true;
        }
    }
    for (WallRow& row : r.wallRows) {
        if (row.allowed > c.restingSpeed) {
            row.allowed = r.restitutionOf(row, c) * row.allowed;
            any = true;
        } else {
            row.allowed = -1.0; // below 0: no bounce
        }
    }
    return any;
}

// 7. Final passes: bouncePasses over every row, velocityPasses when a
// pair bounces. The extra passes a bounce needs go to the rows within
// bounceLayers balls of it when those are fewer than half the rows:
// one ball bouncing on a resting pile of 20,000 then costs a few
// hundred rows a pass instead of the whole pile. The passes over
// every row come last, so every row ends on the same footing.
void StagedSolve::finalPasses(RestingRows& r, const SubStepContext& c, const StageStep& step, bool any)
{
    const ContactSolverSettings& settings = c.solver;
    m_counts.bounced = any;
    const int allPasses = std::max(1, settings.bouncePasses);
    int extraPasses = any ? std::max(0, settings.velocityPasses - allPasses) : 0;
    if (extraPasses > 0 && settings.bounceLayers > 0 && markBounceRegion(r, settings.bounceLayers)) {
        for (int pass = 0; pass < extraPasses; ++pass)
            stagePass(r, c, step, false, true, true, &m_bounceRows);
        m_counts.bounceRows = m_bounceRows.size();
        m_counts.bouncePasses = extraPasses;
        extraPasses = 0;
    }
    const int passes = allPasses + extraPasses;
    for (int pass = 0; pass < passes; ++pass)
        stagePass(r, c, step, false, any, true);
    m_counts.passes += passes;
}

// The bodies within `layers` rows of a bounce, breadth-first over the rows
// (pair_graph.h; layer 0: the bodies of a bouncing pair or of a ball
// bouncing off a wall), and the rows that touch a body of a layer below
// `layers`, in row order. The search runs on one thread, over a graph of the
// rows built at the solve's first region (the rows join the same bodies
// until the solve ends); the rows are listed strip by strip, on every core
// when there are many, and joined in strip order, which is row order. The
// region is the same whatever the thread count. False (and the region
// unused) when it would hold half the bodies or half the rows or more: then
// every row gets every pass, as without a region.
bool StagedSolve::markBounceRegion(const RestingRows& r, int layers, const std::vector<int>* seedRows)
{
    layers = std::min(layers, static_cast<int>(kFarFromBounce) - 1);
    const auto bodies = static_cast<std::size_t>(r.bodyCount);
    m_bodyLayer.assign(bodies, kFarFromBounce);
    m_bounceRegion.clear();
    auto seed = [&](int body) {
        unsigned char& l = m_bodyLayer[static_cast<std::size_t>(body)];
        if (l != 0) {
            l = 0;
            m_bounceRegion.push_back(body);
        }
    };
    if (seedRows) {
        for (const int k : *seedRows) {
            seed(r.pairRows[static_cast<std::size_t>(k)].a);
            seed(r.pairRows[static_cast<std::size_t>(k)].b);
        }
    } else {
        for (std::size_t k = 0; k < r.rowCount; ++k)
            if (m_pushed[k] == 2) {
                seed(r.pairRows[k].a);
                seed(r.pairRows[k].b);
            }
        for (const WallRow& row : r.wallRows)
            if (row.allowed >= 0.0)
                seed(row.body);
    }
    // A region of half the bodies or more has about half the rows or more:
    // the search stops there (in the landing of a pile, where bounces are
    // everywhere).
    if (!m_rowGraph.built())
        m_rowGraph.build(r.bodyCount, r.rowCount, [&r](std::size_t k) { return r.pairRows[k].a; },
                         [&r](std::size_t k) { return r.pairRows[k].b; });
    if (!m_rowGraph.spread(m_bounceRegion, m_bodyLayer, layers, (bodies + 1) / 2))
        return false;
    const std::size_t strips = r.strips.stripCount();
    if (m_stripRegionRows.size() < strips)
        m_stripRegionRows.resize(strips);
    for (std::size_t s = 0; s < strips; ++s)
        m_stripRegionRows[s].clear();
    const unsigned char* layer = m_bodyLayer.data();
    r.strips.run([&](int strip, int begin, int end) {
        std::vector<int>& rows = m_stripRegionRows[static_cast<std::size_t>(strip)];
        for (int k = begin; k < end; ++k) {
            const PairRow& row = r.pairRows[static_cast<std::size_t>(k)];
            if (std::min(layer[row.a], layer[row.b]) < layers)
                rows.push_back(k);
        }
    });
    m_bounceRows.clear();
    for (std::size_t s = 0; s < strips; ++s)
        m_bounceRows.insert(m_bounceRows.end(), m_stripRegionRows[s].begin(), m_stripRegionRows[s].end());
    return 2 * m_bounceRows.size() < r.rowCount;
}

// A row's gap now is its gap at the start of the sub-step plus what its
// bodies moved along its line since (no square root: the line is the one at
// the start). The bodies move only in step 4, so the passes between two
// moves (five at the defaults, more after an impact or a bounce) read one
// gap per row from m_gapNow instead of both bodies' moves: the same sums, to
// the bit. Each strip writes its own rows' entries.
void StagedSolve::updateGaps(RestingRows& r)
{
    const PairRow* rows = r.pairRows.data();
    const double* gap = m_gap.data();
    const BodyPosition* at = r.bodyPositions.data();
    const double* start = m_bodyStart.data();
    double* gapNow = m_gapNow.data();
    r.strips.run([&](int, int begin, int end) {
        for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
            const auto a = static_cast<std::size_t>(rows[k].a), b = static_cast<std::size_t>(rows[k].b);
            const double movedAx = at[a].x - start[2 * a], movedAy = at[a].y - start[2 * a + 1];
            const double movedBx = at[b].x - start[2 * b], movedBy = at[b].y - start[2 * b + 1];
            gapNow[k] = gap[k] + ((movedBx - movedAx) * rows[k].nx + (movedBy - movedAy) * rows[k].ny);
        }
    });
}

// One pass over the rows. A gap (m_gapNow) may close within the stage and
// no more (v_n ≥ −gap/hs); an overlap with `push` asks the soft contact's
// separating speed; with `bounce`, a bouncing row asks its bounce speed.
void StagedSolve::stagePass(RestingRows& r, const SubStepContext& c, const StageStep& step, bool push, bool bounce,
                            bool last, const std::vector<int>* onlyRows)
{
    const PairRow* rows = r.pairRows.data();
    double* impulse = r.impulse.data();
    const double* gapNow = m_gapNow.data();
    RestingBody* body = r.bodies.data();
    const BodyPosition* position = r.bodyPositions.data();
    unsigned char* pushed = m_pushed.data();
    double* hitSpeed = m_hitSpeed.data();
    const double* stageVelocity = m_stageVelocity.data();
    const double pushSpeed = c.solver.pushSpeed;
    // The target −v_n and the share of mass and impulse for a row with gap s.
    auto target = [&](double s, double& bias, double& massScale, double& impulseScale) {
        massScale = 1.0;
        impulseScale = 0.0;
        if (s > 0.0) {
            bias = s * step.inverseHs;
        } else if (push) {
            bias = std::max(step.soft.biasRate * s, -pushSpeed);
            massScale = step.soft.massScale;
            impulseScale = step.soft.impulseScale;
        } else {
            bias = 0.0;
        }
    };
    auto solveRow = [&](std::size_t k) {
        const PairRow& row = rows[k];
        RestingBody& A = body[row.a];
        RestingBody& B = body[row.b];
        const auto a = static_cast<std::size_t>(row.a), b = static_cast<std::size_t>(row.b);
        const double sep = gapNow[k];
        const bool bouncing = bounce && pushed[k] == 2;
        double bias, massScale, impulseScale;
        target(sep, bias, massScale, impulseScale);
        if (bouncing)
            bias = row.allowed; // v_n ≥ e·|v_n0|
        const double vn = normalSpeed(body, row);
        double total = std::max(impulse[k] - massScale * row.mass * (vn + bias) - impulseScale * impulse[k], 0.0);
        // At the end of the last stage a gap no longer limits how fast
        // it may close (the next sub-step's rows will, over the length
        // it moves): such a row may only give back impulse. Not while a
        // bounce is made, for a row that pushed in this sub-step: the pile
        // under a bouncing ball holds it as the contact it was, or the ball
        // it struck sinks into the balls under it and the bounce is lost.
        if (last && sep > 0.0 && !bouncing && !(bounce && pushed[k] != 0))
            total = std::min(total, impulse[k]);
        const double j = total - impulse[k];
        impulse[k] = total;
        if (j != 0.0) {
            applyPair(body, row, j);
            A.changed = 0;
            B.changed = 0;
        }
        if (total > 0.0 && pushed[k] == 0) { // the stage it hits in
            pushed[k] = 1;
            hitSpeed[k] = (stageVelocity[2 * b] - stageVelocity[2 * a]) * row.nx +
                          (stageVelocity[2 * b + 1] - stageVelocity[2 * a + 1]) * row.ny;
        }
    };
    // A region's rows (in row order) go by strip too, each strip's share of
    // the list in four interleaved quarters.
    if (onlyRows) {
        const int* list = onlyRows->data();
        r.strips.runList(*onlyRows, [&](int, int begin, int end) {
            forEachInterleaved(begin, end, [&](std::size_t i) { solveRow(static_cast<std::size_t>(list[i])); });
        });
    } else {
        r.strips.run([&](int, int begin, int end) { forEachInterleaved(begin, end, solveRow); });
    }
    // The walls after the pairs, in key order (rows exist for enabled walls
    // only). A wall does not move, so its gap is the ball's distance to it.
    const double size[2] = {c.box.width, c.box.height};
    for (WallRow& row : r.wallRows) {
        if (onlyRows && m_bodyLayer[static_cast<std::size_t>(row.body)] == kFarFromBounce)
            continue;
        const BodyPosition& p = position[row.body];
        const double coordinate = row.axis == 0 ? p.x : p.y;
        const double s = row.side > 0.0 ? size[row.axis] - p.r - coordinate : coordinate - p.r;
        const bool bouncing = bounce && row.allowed >= 0.0;
        double bias, massScale, impulseScale;
        target(s, bias, massScale, impulseScale);
        if (bouncing)
            bias = -row.allowed; // leaves at e_w times the speed it came with
        double& vk = wallSpeed(body, row);
        const double vn = -row.side * vk; // away from the wall
        double total = std::max(row.impulse - massScale * (vn + bias) / row.w - impulseScale * row.impulse, 0.0);
        if (last && s > 0.0 && !bouncing)
            total = std::min(total, row.impulse);
        if (total > 0.0 && row.allowed == -1.0 && !bounce) // the speed it came at the wall with, at most into0
            row.allowed = std::clamp(row.side * stageVelocity[2 * static_cast<std::size_t>(row.body) +
                                                              static_cast<std::size_t>(row.axis)],
                                     0.0, std::max(row.into0, 0.0));
        const double j = total - row.impulse;
        row.impulse = total;
        if (j != 0.0) {
            vk -= row.side * row.w * j;
            body[row.body].changed = 0;
        }
    }
}

// A body no row ever pushed (a speculative neighbour that never met
// another) takes back what the integrator gave it, so a ball in free flight
// moves the same whether or not it sits near others. RestingRows::writeBack
// then writes the bodies to the balls.
void StagedSolve::keepUntouched(const BallState& balls, RestingRows& r)
{
    const double* x = balls.position.data();
    const double* v = balls.velocity.data();
    for (int i = 0; i < balls.size(); ++i) {
        const auto ii = static_cast<std::size_t>(i);
        const int k = r.bodyOf[ii];
        if (k < 0 || r.bodies[static_cast<std::size_t>(k)].changed >= 0 || r.tookBack[2 * ii] || r.tookBack[2 * ii + 1])
            continue;
        const auto kk = static_cast<std::size_t>(k);
        r.bodies[kk].v[0] = v[2 * i];
        r.bodies[kk].v[1] = v[2 * i + 1];
        r.bodyPositions[kk].x = x[2 * i];
        r.bodyPositions[kk].y = x[2 * i + 1];
    }
}

} // namespace forcelab::sim
