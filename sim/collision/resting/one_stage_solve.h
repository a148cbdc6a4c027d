#pragma once
// The one-stage resting-contact solve (contact_solver.h, points 1-5; used
// when settings.stages = 1): sequential impulses over the rows of
// resting_rows.h in one pass of the sub-step,
//
//   3. warmStart         last sub-step's impulses applied again
//   4. relax             velocity passes until no ball changes speed
//   5. bounce            restitution targets for new pairs that hit, the passes
//                        again, and one wall pass
//   6. moveBodies        positions moved as if the impulses acted at the start
//   7. correctPositions  overlap beyond the slop removed, positions only
//
// each lapped into its own entry of the collision profile. The write-back
// (stage 8) is RestingRows::writeBack.

#include "sim/collision/collision_profile.h"
#include "sim/collision/resting/resting_rows.h"
#include "sim/collision/resting/sub_step_context.h"

namespace forcelab::sim {

class OneStageSolve {
public:
    /// Stages 3-7 on the rows and bodies `r` built for this sub-step.
    RestingCounts solve(RestingRows& r, const SubStepContext& c, StageClock& clock, CollisionProfile& profile);

private:
    void warmStart(RestingRows& r);
    void relax(RestingRows& r, const SubStepContext& c, CollisionProfile& profile, bool profiling);
    void bounce(RestingRows& r, const SubStepContext& c, CollisionProfile& profile, bool profiling);
    void moveBodies(RestingRows& r, const SubStepContext& c);
    void correctPositions(RestingRows& r, const SubStepContext& c);

    int m_passes = 0; // velocity passes over every row in this solve
};

} // namespace forcelab::sim
