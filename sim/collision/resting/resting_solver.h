#pragma once
// The resting-contact solver of contact_solver.h as named stages: sequential
// impulses with accumulated, warm-started impulses over the ball–ball and
// ball–wall contacts. One solve runs
//
//   0. takeBackWallBounces  the wall stage's bounce of a ball it left on a wall
//                        (staged solve: only a bounce slower than v_rest)
//   1. buildPairRows     ball–ball rows (line of impact, effective mass, the
//                        gap at the start, last sub-step's impulse)
//   2. buildWallRows     ball–wall rows for the balls on or near a wall
//
// then, with settings.stages > 1 (the default), the staged solve of
// soft_stages.cpp (point 6 of contact_solver.h):
//
//   3. stagedSolve       the sub-step cut into stages: gravity's share, warm
//                        start, soft passes, move, relax; then the bounces
//   4. stagedWriteBack   bodies no impulse touched keep the integrator's
//                        result; the others go back to the balls
//
// or, with stages = 1, the one-stage solve:
//
//   3. warmStart         last sub-step's impulses applied again
//   4. relax             velocity passes until no ball changes speed
//   5. bounce            restitution targets for new pairs that hit, the passes
//                        again, and one wall pass
//   6. moveBodies        positions moved as if the impulses acted at the start
//   7. correctPositions  overlap beyond the slop removed, positions only
//   8. writeBack         velocities and positions back to the balls
//
// each lapped into its own entry of the collision profile. The balls that
// take part are gathered into bodies (velocity, inverse mass, pass stamp: one
// 32-byte record each) in the order the rows first name them, so the passes
// touch little memory; every operation on a velocity is the one a solver
// working on the balls' columns would make, in the same order.

#include "sim/world/ball_state.h"
#include "sim/collision/collision_profile.h"
#include "sim/collision/contact.h"
#include "sim/collision/resting/pair_graph.h"
#include "sim/collision/resting/row_strips.h"
#include "sim/collision/resting/sub_step_context.h"

#include <cstddef>
#include <cstdint>
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
    const std::vector<unsigned char>& held() const { return m_held; }

    /// Forgets the impulses kept for the next warm start (another kind of
    /// step ran, so they no longer belong to these contacts).
    void forget() { m_warmCount = -1; }
    /// Velocity passes over every row the last solve made.
    int lastPasses() const { return m_lastPasses; }
    /// Rows that alone got the passes a bounce adds in the last solve (the
    /// rows near a bounce); 0 when no pair bounced or every row got them.
    std::size_t lastBounceRows() const { return m_lastBounceRows; }
    /// How many passes those rows got on top of the passes over every row.
    int lastBouncePasses() const { return m_lastBouncePasses; }
    /// Whether a pair or a ball on a wall bounced in the last solve.
    bool lastBounced() const { return m_lastBounced; }

private:
    // One ball–ball contact: its two bodies, the line of impact at detection,
    // the effective mass 1/(wa + wb) and the approach speed it may keep
    // (closes its gap in one sub-step; 0 when it overlaps). 32 bytes and
    // read-only in the passes, which stream these rows many times per
    // sub-step: their size sets the memory traffic. The balls of each row
    // (for the next sub-step's warm-start merge), the total impulse so far and
    // the normal speed before the solve are arrays beside them.
    struct PairRow {
        int a, b;
        double nx, ny;
        float mass, allowed;
    };
    // One ball on a wall: key 4·ball + 2·axis + (far side), its body, axis 0
    // (x) or 1 (y), side +1 (the wall at the box's far edge) or −1 (at 0), the
    // speed towards the wall it may keep (closes the gap by the end of the
    // sub-step, never below 0), inverse mass, speed towards the wall before
    // the solve, total impulse.
    struct WallRow {
        int key, body, axis;
        double side, allowed, w, into0, impulse;
    };
    // A ball that takes part: the velocity the passes change, its inverse
    // mass and the last velocity pass that changed it (−1: none). 32 bytes
    // with padding, so a row update touches one cache line per ball.
    struct Body {
        double v[2];
        double w;
        int changed;
    };
    static_assert(sizeof(Body) == 32);
    // The same bodies for the position stages: position, radius, inverse mass.
    struct BodyPosition {
        double x, y, r, w;
    };

    void prepare(int n);
    int bodyFor(std::size_t i, const BallState& balls);
    void takeBackWallBounces(BallState& balls, const SubStepContext& c);
    void buildPairRows(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                       std::vector<Contact>* touching);
    void buildWallRows(const BallState& balls, const SubStepContext& c);
    void sortRowsByStrip();
    void restoreRowOrder();
    void warmStart();
    void relax(const SubStepContext& c, CollisionProfile& profile, bool profiling);
    void bounce(const SubStepContext& c, CollisionProfile& profile, bool profiling);
    void moveBodies(const SubStepContext& c);
    void correctPositions(const SubStepContext& c);
    void writeBack(BallState& balls, const SubStepContext& c);
    // The staged solve (soft_stages.cpp), replacing stages 3-8 when
    // c.solver.stages > 1.
    void stagedSolve(const SubStepContext& c);
    // A soft contact's constants for one stage of length hs: the share of
    // the overlap pushed apart per second, and how much of the row's mass
    // and of its impulse so far a pushing pass uses (soft_stages.cpp).
    struct SoftContact {
        double hs, inverseHs, biasRate, massScale, impulseScale;
    };
    // One pass over every row (onlyRows null) or over the rows listed.
    void stagePass(const SubStepContext& c, const SoftContact& soft, bool push, bool bounce, bool last,
                   const std::vector<int>* onlyRows = nullptr);
    // The rows near a bounce, for the passes a bounce adds (soft_stages.cpp).
    bool markBounceRegion(int layers, const std::vector<int>* seedRows = nullptr);
    static constexpr unsigned char kFarFromBounce = PairGraph::kFar;
    void stagedWriteBack(BallState& balls, const SubStepContext& c);

    // The passes' two innermost operations, here so that every pass (in
    // resting_solver.cpp and soft_stages.cpp) inlines them.
    // The impulse j along the row's normal: a gets −w_a j n, b gets +w_b j n.
    void applyPair(const PairRow& row, double j)
    {
        Body& ba = m_bodies[static_cast<std::size_t>(row.a)];
        Body& bb = m_bodies[static_cast<std::size_t>(row.b)];
        const double ja = ba.w * j, jb = bb.w * j;
        ba.v[0] -= ja * row.nx;
        ba.v[1] -= ja * row.ny;
        bb.v[0] += jb * row.nx;
        bb.v[1] += jb * row.ny;
    }
    // v_n = (v_b − v_a)·n: negative while the pair approaches.
    double normalSpeed(const PairRow& row) const
    {
        const Body& ba = m_bodies[static_cast<std::size_t>(row.a)];
        const Body& bb = m_bodies[static_cast<std::size_t>(row.b)];
        return (bb.v[0] - ba.v[0]) * row.nx + (bb.v[1] - ba.v[1]) * row.ny;
    }
    double& wallSpeed(const WallRow& row) { return m_bodies[static_cast<std::size_t>(row.body)].v[row.axis]; }

    // The row arrays only grow (rows are written by index, no push_back);
    // the first m_rowCount hold this sub-step's rows.
    std::vector<PairRow> m_pairRows, m_spareRows;
    std::vector<Contact> m_rowBalls, m_spareBalls;
    std::vector<double> m_impulse, m_spareImpulse, m_vn0, m_spareVn0;
    std::vector<double> m_gap;             // per row, staged solve: centre distance less the radii at the start
    std::vector<unsigned char> m_pushed;   // per row, staged solve: its impulse was above 0 in some stage
    std::vector<double> m_hitSpeed;        // per row, staged solve: v_n at the start of the stage it first pushed in
    std::vector<double> m_stageVelocity;   // per body, staged solve: v at the start of this stage
    std::vector<double> m_bodyStart;       // per body, staged solve: x, y at the start of the sub-step
    std::vector<double> m_bodyMoved;       // per body, staged solve: x, y now less x, y at the start
    std::vector<unsigned char> m_bodyLayer; // per body, staged solve: rows between it and a bounce (kFarFromBounce: more)
    std::vector<int> m_bounceRows;         // staged solve: the rows near a bounce, in row order
    std::vector<unsigned char> m_hitNoted; // per row, staged solve: its first push was looked at
    std::vector<int> m_stageHits;          // staged solve: the rows a hard impact first pushed in this stage
    std::vector<int> m_bounceRegion;       // staged solve: the bodies near a bounce, in the order reached
    PairGraph m_rowGraph;                  // staged solve: the rows as a graph of bodies, for the region
    std::size_t m_rowCount = 0;
    std::vector<WallRow> m_wallRows, m_spareWalls;
    std::vector<Body> m_bodies;
    std::vector<BodyPosition> m_bodyPositions;
    std::vector<int> m_bodyOf; // per ball: its body in this solve (−1: none; all −1 between solves)
    std::vector<unsigned char> m_held; // per ball: an impulse touched it in the last solve
    const unsigned char* m_asleep = nullptr; // per ball, this solve: it sleeps (nullptr: none does)
    // The pairs of two sleepers, not solved, in (a, b) order, with the
    // impulse they had when their second ball fell asleep: their warm start
    // when they wake.
    std::vector<Contact> m_dormantBalls, m_spareDormantBalls;
    std::vector<double> m_dormantImpulse, m_spareDormantImpulse;
    std::vector<double> m_bodyVelocity0;
    std::vector<double> m_bodyShift;       // per body, px: x, y to add to x − v·h for its start (sub_step_context.h)
    double m_startShift[2] = {0.0, 0.0};   // this solve, px: startLag·g·h² along x and y
    std::vector<unsigned char> m_tookBack;   // per ball and axis: 1 when stage 0 took its bounce back
    RowStrips m_strips;                      // the rows cut into strips for the passes (row_strips.h)
    std::vector<unsigned char> m_stripMoved; // per strip, this pass: a ball changed by more than the tolerance
    std::vector<std::int64_t> m_stripSolves; // per strip, this pass: rows solved
    int m_bodyCount = 0;
    int m_warmCount = -1;
    int m_lastPasses = 0;
    std::size_t m_lastBounceRows = 0;
    int m_lastBouncePasses = 0;
    bool m_lastBounced = false;
};

} // namespace forcelab::sim
