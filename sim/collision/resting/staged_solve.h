#pragma once
// The staged resting-contact solve (contact_solver.h, point 6; used when
// settings.stages > 1, the default), after Box2D v3's soft step: the rows of
// resting_rows.h, found once per sub-step, solved in `stages` short stages
// of hs = h / stages.
//
//   start        the bodies back where the sub-step began, each row's line
//                and gap from there
//   runStage     per stage: gravity's share, warm start, soft passes
//                (soft_contact.h), the passes a hard impact adds, move
//                (and the rows' gaps after it: updateGaps), relax
//   markBounces  the pairs and walls that bounce, at the speed they hit with
//   finalPasses  the passes over every row, and the bounce region's extras
//
// keepUntouched then gives a body no impulse touched back what the
// integrator made of it, before RestingRows::writeBack.

#include "sim/world/ball_state.h"
#include "sim/collision/resting/pair_graph.h"
#include "sim/collision/resting/resting_rows.h"
#include "sim/collision/resting/soft_contact.h"
#include "sim/collision/resting/sub_step_context.h"

#include <cstddef>
#include <vector>

namespace forcelab::sim {

class StagedSolve {
public:
    /// Solves the rows and bodies `r` built for this sub-step in stages.
    RestingCounts solve(RestingRows& r, const SubStepContext& c);
    /// A body no row ever pushed (a speculative neighbour that never met
    /// another) gets the velocity and position of its ball back.
    void keepUntouched(const BallState& balls, RestingRows& r);

private:
    // One stage's length, its inverse and the soft contact over it.
    struct StageStep {
        double hs = 0.0, inverseHs = 0.0;
        Softness soft;
    };
    static constexpr unsigned char kFarFromBounce = PairGraph::kFar;

    void start(RestingRows& r, const SubStepContext& c);
    void runStage(RestingRows& r, const SubStepContext& c, const StageStep& step, bool last);
    bool markBounces(RestingRows& r, const SubStepContext& c);
    void finalPasses(RestingRows& r, const SubStepContext& c, const StageStep& step, bool any);
    // The rows near a bounce, for the passes a bounce adds.
    bool markBounceRegion(const RestingRows& r, int layers, const std::vector<int>* seedRows = nullptr);
    // Each row's gap now, from its gap at the start and its bodies' moves
    // (constant between two moves, so worked out once per move, not per pass).
    void updateGaps(RestingRows& r);
    // One pass over every row (onlyRows null) or over the rows listed.
    void stagePass(RestingRows& r, const SubStepContext& c, const StageStep& step, bool push, bool bounce, bool last,
                   const std::vector<int>* onlyRows = nullptr);

    std::vector<double> m_gap;             // per row: centre distance less the radii at the start
    std::vector<double> m_gapNow;          // per row: m_gap plus its bodies' moves along its line (updateGaps)
    std::vector<unsigned char> m_pushed;   // per row: its impulse was above 0 in some stage (2: it bounces)
    std::vector<double> m_hitSpeed;        // per row: v_n at the start of the stage it first pushed in
    std::vector<unsigned char> m_hitNoted; // per row: its first push was looked at
    std::vector<double> m_stageVelocity;   // per body: v at the start of this stage
    std::vector<double> m_bodyStart;       // per body: x, y at the start of the sub-step
    std::vector<unsigned char> m_bodyLayer; // per body: rows between it and a bounce (kFarFromBounce: more)
    std::vector<int> m_bounceRows;         // the rows near a bounce, in row order
    std::vector<std::vector<int>> m_stripRegionRows; // per strip: its rows near a bounce (markBounceRegion)
    std::vector<int> m_stageHits;          // the rows a hard impact first pushed in this stage
    std::vector<int> m_bounceRegion;       // the bodies near a bounce, in the order reached
    PairGraph m_rowGraph;                  // the rows as a graph of bodies, for the region
    RestingCounts m_counts;                // this solve's passes and bounces
};

} // namespace forcelab::sim
