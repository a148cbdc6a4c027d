// The staged solve of the resting solver (contact_solver.h, point 6): the
// sub-step's contacts, found once, are solved in `stages` short stages of
// length hs = h / stages. Each stage gives the bodies their share of gravity,
// applies the contacts' impulses again (warm start), pushes overlaps apart
// through the velocities with soft contacts, moves the bodies, and takes the
// push out of the velocities again (relax). The bounces come last.

#include "sim/collision/resting/resting_solver.h"

#include "sim/collision/response/positional_correction.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace forcelab::sim {

// A soft contact is a stiff spring with a damper, solved implicitly over one
// stage: with ω = 2π·stiffness/hs (the spring frequency a share of the stage
// rate), ζ the damping ratio and hs the stage,
//   a1 = 2ζ + hs·ω,  a2 = hs·ω·a1,  a3 = 1 / (1 + a2),
// an overlap s < 0 asks for the separating speed −s·ω/a1 (biasRate), and the
// impulse that meets it is scaled by a2·a3 (massScale) less a3 times the
// impulse already applied (impulseScale). However long the stage, the
// spring cannot overshoot, so the push never feeds energy into a pile the
// way a rigid correction of the whole overlap does.
void RestingSolver::stagedSolve(const SubStepContext& c)
{
    const ContactSolverSettings& settings = c.solver;
    const int stages = std::max(1, settings.stages);
    SoftContact soft{};
    soft.hs = c.h / stages;
    soft.inverseHs = 1.0 / soft.hs;
    const double omega = 2.0 * std::numbers::pi * settings.contactStiffness * soft.inverseHs;
    const double a1 = 2.0 * settings.dampingRatio + soft.hs * omega;
    const double a2 = soft.hs * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    soft.biasRate = omega / a1;
    soft.massScale = a2 * a3;
    soft.impulseScale = a3;

    // The bodies at the start of the sub-step: the integrator moved each by
    // about v·h (a ball whose wall bounce stage 0 took back: from the wall;
    // explicit Euler by g·h² less, sub_step_context.h) and gave it g·h of
    // speed; both are taken back, and each stage gives g·hs again.
    const auto bodies = static_cast<std::size_t>(m_bodyCount);
    if (m_bodyStart.size() < 2 * bodies) {
        m_bodyStart.resize(2 * bodies);
        m_bodyMoved.resize(2 * bodies);
        m_stageVelocity.resize(2 * bodies);
    }
    std::fill_n(m_bodyMoved.begin(), 2 * bodies, 0.0);
    // A ball the wall stage has just bounced (its new velocity would take it
    // back beyond the wall) starts where the wall stage left it along that
    // axis.
    const bool on[2][2] = {{c.walls.left, c.walls.right}, {c.walls.top, c.walls.bottom}};
    const double size[2] = {c.box.width, c.box.height};
    for (std::size_t k = 0; k < bodies; ++k) {
        BodyPosition& p = m_bodyPositions[k];
        double* at[2] = {&p.x, &p.y};
        for (int axis = 0; axis < 2; ++axis) {
            const std::size_t ka = 2 * k + static_cast<std::size_t>(axis);
            const double q = *at[axis] - m_bodyVelocity0[ka] * c.h + m_bodyShift[ka];
            const bool beyond = (on[axis][0] && q - p.r < 0.0) || (on[axis][1] && size[axis] - p.r - q < 0.0);
            if (!beyond)
                *at[axis] = q;
        }
        m_bodyStart[2 * k] = p.x;
        m_bodyStart[2 * k + 1] = p.y;
        if (m_bodies[k].w > 0.0) { // a sleeper (w = 0) was given nothing and gets nothing
            m_bodies[k].v[0] -= c.gravityX * c.h;
            m_bodies[k].v[1] -= c.gravityY * c.h;
        }
        m_bodies[k].changed = -1; // −1: no impulse has touched it yet
    }
    // Each row's line of impact and gap from its bodies' start positions (the
    // wall stage may have moved one ball of a pair back onto a wall).
    if (m_gap.size() < m_rowCount)
        m_gap.resize(m_rowCount);
    for (std::size_t k = 0; k < m_rowCount; ++k) {
        PairRow& row = m_pairRows[k];
        const BodyPosition& A = m_bodyPositions[static_cast<std::size_t>(row.a)];
        const BodyPosition& B = m_bodyPositions[static_cast<std::size_t>(row.b)];
        const double dx = B.x - A.x, dy = B.y - A.y, reach = A.r + B.r;
        const double len = std::sqrt(dx * dx + dy * dy);
        if (len > 1e-12 * reach && std::isfinite(len)) {
            row.nx = dx / len;
            row.ny = dy / len;
        }
        m_gap[k] = len - reach;
    }
    m_pushed.assign(m_rowCount, 0);
    m_hitSpeed.assign(m_rowCount, 0.0);
    m_hitNoted.assign(m_rowCount, 0);
    m_stageHits.clear();
    const int impactPasses = std::max(0, settings.velocityPasses - std::max(1, settings.stagePasses));
    // A wall row's `allowed` holds, until the bounces, the speed its ball
    // came at the wall when the row first pushed: −1 until then, −2 for a
    // row that pushed in the last sub-step already (a resting ball).
    for (WallRow& row : m_wallRows)
        row.allowed = row.impulse > 0.0 ? -2.0 : -1.0;
    const double gx = c.gravityX * soft.hs, gy = c.gravityY * soft.hs;
    const int stagePasses = std::max(1, settings.stagePasses), relaxPasses = std::max(0, settings.relaxPasses);
    for (int stage = 0; stage < stages; ++stage) {
        // 1. Gravity's share: dv = g·hs. The speeds then are the ones a
        //    new contact of this stage hits with.
        for (std::size_t k = 0; k < bodies; ++k) {
            const double share = m_bodies[k].w > 0.0 ? 1.0 : 0.0; // a sleeper stays at rest
            m_bodies[k].v[0] += share * gx;
            m_bodies[k].v[1] += share * gy;
            m_stageVelocity[2 * k] = m_bodies[k].v[0];
            m_stageVelocity[2 * k + 1] = m_bodies[k].v[1];
        }
        // 2. Warm start: every contact's impulse of the stage before (of the
        //    last sub-step at the first stage) applied again, since gravity
        //    has added the same speed again.
        m_strips.run([&](int, int begin, int end) {
            for (int k = begin; k < end; ++k) {
                const double j = m_impulse[static_cast<std::size_t>(k)];
                if (j > 0.0) {
                    const PairRow& row = m_pairRows[static_cast<std::size_t>(k)];
                    applyPair(row, j);
                    m_bodies[static_cast<std::size_t>(row.a)].changed = 0;
                    m_bodies[static_cast<std::size_t>(row.b)].changed = 0;
                }
            }
        });
        for (const WallRow& row : m_wallRows)
            if (row.impulse > 0.0) {
                wallSpeed(row) -= row.side * row.w * row.impulse;
                m_bodies[static_cast<std::size_t>(row.body)].changed = 0;
            }
        // 3. Passes that stop approaches and push overlaps apart (soft).
        for (int pass = 0; pass < stagePasses; ++pass)
            stagePass(c, soft, true, false, false);
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
        for (std::size_t k = 0; k < m_rowCount; ++k)
            if (m_pushed[k] != 0 && !m_hitNoted[k]) {
                m_hitNoted[k] = 1;
                if (m_vn0[k] != 0.0 && -m_hitSpeed[k] > c.restingSpeed)
                    m_stageHits.push_back(static_cast<int>(k));
            }
        if (!m_stageHits.empty() && impactPasses > 0) {
            const bool region = settings.bounceLayers > 0 && markBounceRegion(settings.bounceLayers, &m_stageHits);
            if (region || m_rowCount <= static_cast<std::size_t>(settings.impactRows)) {
                for (int pass = 0; pass < impactPasses; ++pass)
                    stagePass(c, soft, false, false, false, region ? &m_bounceRows : nullptr);
                m_lastPasses += impactPasses;
            }
        }
        // 4. The bodies move by their speeds, never through an enabled wall.
        for (std::size_t k = 0; k < bodies; ++k) {
            BodyPosition& p = m_bodyPositions[k];
            const Vec2 from(p.x, p.y);
            Vec2 to(p.x + m_bodies[k].v[0] * soft.hs, p.y + m_bodies[k].v[1] * soft.hs);
            keepInsideWalls(from, to, p.r, c.box, c.walls);
            p.x = to.x();
            p.y = to.y();
            m_bodyMoved[2 * k] = p.x - m_bodyStart[2 * k];
            m_bodyMoved[2 * k + 1] = p.y - m_bodyStart[2 * k + 1];
        }
        // 5. Relax: passes without the push, so the speed that pushed the
        //    overlaps apart does not stay in the bodies.
        for (int pass = 0; pass < relaxPasses; ++pass)
            stagePass(c, soft, false, false, stage + 1 == stages);
        m_lastPasses += stagePasses + relaxPasses;
    }
    // 6. Bounces. A new contact (no impulse in the last sub-step) whose pair
    //    came together faster than the resting speed separates at e times
    //    the speed it hit with; a ball that came at a wall that fast leaves
    //    at e_w times its speed. The speed it hit with is the one in the
    //    stage where it first pushed: the speed at the end of the sub-step
    //    has up to g·h more in it, and a bounce at e·(v + g·h) gains energy
    //    for every v below e·g·h/(1 − e) (150 px/s at 60 Hz, e = 0.9), so
    //    slow bouncers would never settle. The other rows keep what relax
    //    asks, so the pile under a bouncing ball holds.
    bool any = false;
    for (std::size_t k = 0; k < m_rowCount; ++k) {
        const double hit = std::max(m_hitSpeed[k], m_vn0[k]); // never faster than at the end
        if (m_vn0[k] != 0.0 && -hit > c.restingSpeed && m_pushed[k]) {
            m_pairRows[k].allowed = static_cast<float>(c.restitution * hit); // v_n ≥ e·|v_hit|
            m_pushed[k] = 2;
            any = true;
        }
    }
    for (WallRow& row : m_wallRows) {
        if (row.allowed > c.restingSpeed) {
            row.allowed = c.walls.restitution * row.allowed;
            any = true;
        } else {
            row.allowed = -1.0; // below 0: no bounce
        }
    }
    // 7. Final passes: bouncePasses over every row, velocityPasses when a
    //    pair bounces. The extra passes a bounce needs go to the rows within
    //    bounceLayers balls of it when those are fewer than half the rows:
    //    one ball bouncing on a resting pile of 20,000 then costs a few
    //    hundred rows a pass instead of the whole pile. The passes over
    //    every row come last, so every row ends on the same footing.
    m_lastBounced = any;
    const int allPasses = std::max(1, settings.bouncePasses);
    int extraPasses = any ? std::max(0, settings.velocityPasses - allPasses) : 0;
    if (extraPasses > 0 && settings.bounceLayers > 0 && markBounceRegion(settings.bounceLayers)) {
        for (int pass = 0; pass < extraPasses; ++pass)
            stagePass(c, soft, false, true, true, &m_bounceRows);
        m_lastBounceRows = m_bounceRows.size();
        m_lastBouncePasses = extraPasses;
        extraPasses = 0;
    }
    const int finalPasses = allPasses + extraPasses;
    for (int pass = 0; pass < finalPasses; ++pass)
        stagePass(c, soft, false, any, true);
    m_lastPasses += finalPasses;
}

// The bodies within `layers` rows of a bounce, breadth-first over the rows
// (pair_graph.h; layer 0: the bodies of a bouncing pair or of a ball
// bouncing off a wall), and the rows that touch a body of a layer below
// `layers`, in row order. On one thread, so the region is the same whatever
// the thread count. False (and the region unused) when it would hold half
// the bodies or half the rows or more: then every row gets every pass, as
// without a region.
bool RestingSolver::markBounceRegion(int layers, const std::vector<int>* seedRows)
{
    layers = std::min(layers, static_cast<int>(kFarFromBounce) - 1);
    const auto bodies = static_cast<std::size_t>(m_bodyCount);
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
            seed(m_pairRows[static_cast<std::size_t>(k)].a);
            seed(m_pairRows[static_cast<std::size_t>(k)].b);
        }
    } else {
        for (std::size_t k = 0; k < m_rowCount; ++k)
            if (m_pushed[k] == 2) {
                seed(m_pairRows[k].a);
                seed(m_pairRows[k].b);
            }
        for (const WallRow& row : m_wallRows)
            if (row.allowed >= 0.0)
                seed(row.body);
    }
    // A region of half the bodies or more has about half the rows or more:
    // the search stops there (in the landing of a pile, where bounces are
    // everywhere).
    m_rowGraph.build(m_bodyCount, m_rowCount, [this](std::size_t k) { return m_pairRows[k].a; },
                     [this](std::size_t k) { return m_pairRows[k].b; });
    if (!m_rowGraph.spread(m_bounceRegion, m_bodyLayer, layers, (bodies + 1) / 2))
        return false;
    m_bounceRows.clear();
    for (std::size_t k = 0; k < m_rowCount; ++k) {
        const unsigned char la = m_bodyLayer[static_cast<std::size_t>(m_pairRows[k].a)];
        const unsigned char lb = m_bodyLayer[static_cast<std::size_t>(m_pairRows[k].b)];
        if (std::min(la, lb) < layers)
            m_bounceRows.push_back(static_cast<int>(k));
    }
    return 2 * m_bounceRows.size() < m_rowCount;
}

// One pass over the rows. A row's gap now is its gap at the start of the
// sub-step plus what its bodies moved along its line since (no square root:
// the line is the one at the start). A gap may close within the stage and
// no more (v_n ≥ −gap/hs); an overlap with `push` asks the soft contact's
// separating speed; with `bounce`, a bouncing row asks its bounce speed.
void RestingSolver::stagePass(const SubStepContext& c, const SoftContact& soft, bool push, bool bounce, bool last,
                              const std::vector<int>* onlyRows)
{
    const PairRow* rows = m_pairRows.data();
    double* impulse = m_impulse.data();
    const double* gap = m_gap.data();
    Body* body = m_bodies.data();
    const BodyPosition* position = m_bodyPositions.data();
    const double* moved = m_bodyMoved.data();
    unsigned char* pushed = m_pushed.data();
    double* hitSpeed = m_hitSpeed.data();
    const double* stageVelocity = m_stageVelocity.data();
    const double pushSpeed = c.solver.pushSpeed;
    // The target −v_n and the share of mass and impulse for a row with gap s.
    auto target = [&](double s, double& bias, double& massScale, double& impulseScale) {
        massScale = 1.0;
        impulseScale = 0.0;
        if (s > 0.0) {
            bias = s * soft.inverseHs;
        } else if (push) {
            bias = std::max(soft.biasRate * s, -pushSpeed);
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
        } else {
            bias = 0.0;
        }
    };
    auto solveRow = [&](std::size_t k) {
        const PairRow& row = rows[k];
        Body& A = body[row.a];
        Body& B = body[row.b];
        const auto a = static_cast<std::size_t>(row.a), b = static_cast<std::size_t>(row.b);
        const double sep =
            gap[k] + ((moved[2 * b] - moved[2 * a]) * row.nx + (moved[2 * b + 1] - moved[2 * a + 1]) * row.ny);
        const bool bouncing = bounce && pushed[k] == 2;
        double bias, massScale, impulseScale;
        target(sep, bias, massScale, impulseScale);
        if (bouncing)
            bias = row.allowed; // v_n ≥ e·|v_n0|
        const double vn = normalSpeed(row);
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
            applyPair(row, j);
            A.changed = 0;
            B.changed = 0;
        }
        if (total > 0.0 && pushed[k] == 0) { // the stage it hits in
            pushed[k] = 1;
            hitSpeed[k] = (stageVelocity[2 * b] - stageVelocity[2 * a]) * row.nx +
                          (stageVelocity[2 * b + 1] - stageVelocity[2 * a + 1]) * row.ny;
        }
    };
    // A region's rows are few: in row order on this thread.
    if (onlyRows) {
        for (const int k : *onlyRows)
            solveRow(static_cast<std::size_t>(k));
    } else {
        m_strips.run([&](int, int begin, int end) { forEachInterleaved(begin, end, solveRow); });
    }
    // The walls after the pairs, in key order (rows exist for enabled walls
    // only). A wall does not move, so its gap is the ball's distance to it.
    const double size[2] = {c.box.width, c.box.height};
    for (WallRow& row : m_wallRows) {
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
        double& vk = wallSpeed(row);
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
// moves the same whether or not it sits near others; then the one-stage
// write-back.
void RestingSolver::stagedWriteBack(BallState& balls, const SubStepContext& c)
{
    const double* x = balls.position.data();
    const double* v = balls.velocity.data();
    for (int i = 0; i < balls.size(); ++i) {
        const auto ii = static_cast<std::size_t>(i);
        const int k = m_bodyOf[ii];
        if (k < 0 || m_bodies[static_cast<std::size_t>(k)].changed >= 0 || m_tookBack[2 * ii] || m_tookBack[2 * ii + 1])
            continue;
        const auto kk = static_cast<std::size_t>(k);
        m_bodies[kk].v[0] = v[2 * i];
        m_bodies[kk].v[1] = v[2 * i + 1];
        m_bodyPositions[kk].x = x[2 * i];
        m_bodyPositions[kk].y = x[2 * i + 1];
    }
    writeBack(balls, c);
}

} // namespace forcelab::sim
