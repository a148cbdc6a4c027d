// The resting-contact solver (resting_solver.h): the rows built once, then
// the staged or the one-stage solve, then the write-back.

#include "sim/collision/resting/resting_solver.h"

namespace forcelab::sim {

void RestingSolver::solve(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                          std::vector<Contact>* touching, StageClock& clock, CollisionProfile& profile,
                          const unsigned char* asleep)
{
    m_rows.build(balls, c, pairs, touching, clock, profile, asleep);
    m_last = RestingCounts{};
    if (c.solver.stages > 1)
        solveStaged(balls, c, clock, profile);
    else
        solveOneStage(balls, c, clock, profile);
    // The free islands' pairs: their balls have no body, so this may come
    // after the write-back.
    if (!m_rows.freePairs.empty() && resolveFreePairs(balls, c, m_rows.freePairs))
        m_last.bounced = true;
    clock.lap(profile.correction);
}

void RestingSolver::solveStaged(BallState& balls, const SubStepContext& c, StageClock& clock,
                                CollisionProfile& profile)
{
    m_last = m_staged.solve(m_rows, c);
    if (clock.on()) {
        profile.rows += static_cast<std::int64_t>(m_rows.rowCount);
        profile.solves += static_cast<std::int64_t>(m_rows.rowCount) * m_last.passes +
                          static_cast<std::int64_t>(m_last.bounceRows) * m_last.bouncePasses;
    }
    clock.lap(profile.velocity);
    m_staged.keepUntouched(balls, m_rows);
    m_rows.writeBack(balls, c);
    m_rows.restoreRowOrder();
    clock.lap(profile.position);
}

void RestingSolver::solveOneStage(BallState& balls, const SubStepContext& c, StageClock& clock,
                                  CollisionProfile& profile)
{
    m_last = m_oneStage.solve(m_rows, c, clock, profile);
    m_rows.writeBack(balls, c);
    m_rows.restoreRowOrder();
    clock.lap(profile.position);
}

} // namespace forcelab::sim
