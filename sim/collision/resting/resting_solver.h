#pragma once
// The resting-contact solver of contact_solver.h: sequential impulses with
// accumulated, warm-started impulses over the ball–ball and ball–wall
// contacts. One solve builds the rows and bodies (resting_rows.h, stages
// 0-2), then runs one of two algorithms on them:
//
//   - with settings.stages > 1 (the default), the staged solve of
//     staged_solve.h: the sub-step cut into stages with soft contacts, then
//     the bounces;
//   - with stages = 1, the one-stage solve of one_stage_solve.h: warm start,
//     velocity passes, bounces, move and positional correction;
//
// and writes the bodies back to the balls, keeping the impulses for the
// next sub-step's warm start. Each stage is lapped into its own entry of the
// collision profile.

#include "sim/world/ball_state.h"
#include "sim/collision/collision_profile.h"
#include "sim/collision/contact.h"
#include "sim/collision/resting/one_stage_solve.h"
#include "sim/collision/resting/resting_rows.h"
#include "sim/collision/resting/staged_solve.h"
#include "sim/collision/resting/sub_step_context.h"

#include <cstddef>
#include <vector>

namespace forcelab::sim {

class RestingSolver {
public:
    /// Solves the contacts `pairs` (touching and speculative, in (a, b)
    /// order) for one sub-step. When `touching` is given, the pairs of
    /// `pairs` that overlap now are written to it and flagged in
    /// balls.colliding (otherwise `pairs` are the touching ones, already
    /// flagged). `asleep` (per ball, or nullptr: none) marks the sleeping
    /// balls (sleep.h): bodies of infinite mass at rest, with no rows between
    /// two of them and no wall rows.
    void solve(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
               std::vector<Contact>* touching, StageClock& clock, CollisionProfile& profile,
               const unsigned char* asleep = nullptr);
    /// Per ball, whether an impulse (a pair's or a wall's) touched it in the
    /// last solve.
    const std::vector<unsigned char>& held() const { return m_rows.held(); }

    /// Forgets the impulses kept for the next warm start (another kind of
    /// step ran, so they no longer belong to these contacts).
    void forget() { m_rows.forget(); }
    /// Velocity passes over every row the last solve made.
    int lastPasses() const { return m_last.passes; }
    /// Rows that alone got the passes a bounce adds in the last solve (the
    /// rows near a bounce); 0 when no pair bounced or every row got them.
    std::size_t lastBounceRows() const { return m_last.bounceRows; }
    /// How many passes those rows got on top of the passes over every row.
    int lastBouncePasses() const { return m_last.bouncePasses; }
    /// Whether a pair or a ball on a wall bounced in the last solve.
    bool lastBounced() const { return m_last.bounced; }

private:
    void solveStaged(BallState& balls, const SubStepContext& c, StageClock& clock, CollisionProfile& profile);
    void solveOneStage(BallState& balls, const SubStepContext& c, StageClock& clock, CollisionProfile& profile);

    RestingRows m_rows;         // the rows and bodies both algorithms solve
    StagedSolve m_staged;       // stages > 1
    OneStageSolve m_oneStage;   // stages = 1
    RestingCounts m_last;       // the last solve's passes and bounces
};

} // namespace forcelab::sim
