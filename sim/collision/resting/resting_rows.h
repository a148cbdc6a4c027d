#pragma once
// The rows and bodies of one resting-contact solve, shared by its two
// algorithms (the one-stage solve of one_stage_solve.h and the staged solve
// of staged_solve.h). RestingRows builds them from the balls and the pairs:
//
//   0. takeBackWallBounces  the wall stage's bounce of a ball it left on a wall
//                        (staged solve: only a bounce slower than v_rest)
//   1. buildPairRows     ball–ball rows (line of impact, effective mass, the
//                        gap at the start, last sub-step's impulse)
//   2. buildWallRows     ball–wall rows for the balls on or near a wall
//
// then cuts the rows into strips (row_strips.h) and, after a solve, writes
// the bodies back to the balls and keeps the impulses for the next warm
// start. The balls that take part are gathered into bodies (velocity,
// inverse mass, pass stamp: one 32-byte record each) in the order the rows
// first name them, so the passes touch little memory; every operation on a
// velocity is the one a solver working on the balls' columns would make, in
// the same order.

#include "sim/world/ball_state.h"
#include "sim/collision/collision_profile.h"
#include "sim/collision/contact.h"
#include "sim/collision/resting/contact_islands.h"
#include "sim/collision/resting/free_impacts.h"
#include "sim/collision/resting/row_strips.h"
#include "sim/collision/resting/sub_step_context.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace forcelab::sim {

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
struct RestingBody {
    double v[2];
    double w;
    int changed;
};
static_assert(sizeof(RestingBody) == 32);

// The same bodies for the position stages: position, radius, inverse mass.
struct BodyPosition {
    double x, y, r, w;
};

// What a solve reports: velocity passes over every row, the rows that alone
// got the passes a bounce adds (0: no pair bounced, or every row got them),
// how many passes those were, and whether a pair or a wall bounced.
struct RestingCounts {
    int passes = 0;
    std::size_t bounceRows = 0;
    int bouncePasses = 0;
    bool bounced = false;
};

// The passes' two innermost operations, inline so that every pass of both
// solves inlines them.
// The impulse j along the row's normal: a gets −w_a j n, b gets +w_b j n.
inline void applyPair(RestingBody* bodies, const PairRow& row, double j)
{
    RestingBody& ba = bodies[static_cast<std::size_t>(row.a)];
    RestingBody& bb = bodies[static_cast<std::size_t>(row.b)];
    const double ja = ba.w * j, jb = bb.w * j;
    ba.v[0] -= ja * row.nx;
    ba.v[1] -= ja * row.ny;
    bb.v[0] += jb * row.nx;
    bb.v[1] += jb * row.ny;
}
// v_n = (v_b − v_a)·n: negative while the pair approaches.
inline double normalSpeed(const RestingBody* bodies, const PairRow& row)
{
    const RestingBody& ba = bodies[static_cast<std::size_t>(row.a)];
    const RestingBody& bb = bodies[static_cast<std::size_t>(row.b)];
    return (bb.v[0] - ba.v[0]) * row.nx + (bb.v[1] - ba.v[1]) * row.ny;
}
// The velocity component of a wall row's body along its axis.
inline double& wallSpeed(RestingBody* bodies, const WallRow& row)
{
    return bodies[static_cast<std::size_t>(row.body)].v[row.axis];
}

// p moved by (dx, dy) without crossing an enabled wall it was inside.
void moveWithinWalls(double& px, double& py, double r, double dx, double dy, const SubStepContext& c);

class RestingRows {
public:
    /// Stages 0-2 and the strip sort for the contacts `pairs` (see
    /// RestingSolver::solve for `touching` and `asleep`), each lapped into
    /// the profile.
    void build(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
               std::vector<Contact>* touching, StageClock& clock, CollisionProfile& profile,
               const unsigned char* asleep);
    /// Velocities and positions of the bodies back to the balls, in ball
    /// order; every ball is without a body again.
    void writeBack(BallState& balls, const SubStepContext& c);
    /// The impulses back in (a, b) order, for the next sub-step's warm start.
    void restoreRowOrder();
    /// Per ball, whether an impulse touched it in the last solve.
    const std::vector<unsigned char>& held() const { return m_held; }
    /// The restitution a pair row bounces with: the world's, or the smaller
    /// of its balls' own (ball_state.h, pairRestitution).
    double restitutionOf(const PairRow& row, const SubStepContext& c) const
    {
        return c.ownRestitution ? pairRestitution(bodyRestitution[static_cast<std::size_t>(row.a)],
                                                  bodyRestitution[static_cast<std::size_t>(row.b)], c.restitution)
                                : c.restitution;
    }
    /// The restitution a wall row's ball bounces off its wall with.
    double restitutionOf(const WallRow& row, const SubStepContext& c) const
    {
        return c.ownRestitution
                   ? effectiveRestitution(bodyRestitution[static_cast<std::size_t>(row.body)], c.walls.restitution)
                   : c.walls.restitution;
    }
    /// Forgets the impulses kept for the next warm start.
    void forget() { m_warmCount = -1; }

    // What the solves read and change. The row arrays only grow (rows are
    // written by index, no push_back); the first rowCount hold this
    // sub-step's rows, in strip order between build() and restoreRowOrder().
    std::vector<PairRow> pairRows;
    std::vector<double> impulse;          // per row: total impulse so far
    std::vector<double> vn0;              // per row: normal speed before the solve (0: it rested)
    std::size_t rowCount = 0;
    std::vector<WallRow> wallRows;
    std::vector<RestingBody> bodies;
    std::vector<BodyPosition> bodyPositions;
    std::vector<double> bodyVelocity0;    // per body: x, y velocity the integrator moved it by
    std::vector<double> bodyShift;        // per body, px: x, y to add to x − v·h for its start (sub_step_context.h)
    std::vector<double> bodyRestitution;  // per body: its ball's own restitution (read only with c.ownRestitution)
    std::vector<int> bodyOf;              // per ball: its body in this solve (−1: none; all −1 between solves)
    std::vector<unsigned char> tookBack;  // per ball and axis: 1 when stage 0 took its bounce back
    RowStrips strips;                     // the rows cut into strips for the passes (row_strips.h)
    std::vector<unsigned char> stripMoved; // per strip, this pass: a ball changed by more than the tolerance
    std::vector<std::int64_t> stripSolves; // per strip, this pass: rows solved
    std::vector<FreePair> freePairs;      // the meeting pairs of the free islands, in (a, b) order (no rows)
    int bodyCount = 0;

private:
    void prepare(int n);
    int bodyFor(std::size_t i, const BallState& balls);
    void takeBackWallBounces(BallState& balls, const SubStepContext& c);
    void buildPairRows(BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                       std::vector<Contact>* touching);
    void buildWallRows(const BallState& balls, const SubStepContext& c);
    void sortRowsByStrip();

    // What the first loop of buildPairRows found for each pair: its kind,
    // and for a pair that rests or meets its start geometry (a pair that
    // does not meet, the commonest in a gas, keeps one byte; the rare one
    // that becomes a row finds its geometry again, to the same bits).
    enum PairKind : unsigned char { kNone, kQuiet, kRow, kMeets }; // no row; does not meet; rests; meets this sub-step
    struct PairStart {
        double nx, ny, gapStart, approach, warm, wa, wb;
    };
    // Last sub-step's impulse of a pair (0: none), from its rows and its
    // pairs of two sleepers, both in (a, b) order: one walk beside the
    // pairs, so ask for the pairs in (a, b) order.
    class WarmStarts {
    public:
        explicit WarmStarts(const RestingRows& rows) : m_rows(rows) {}
        double of(const Contact& ct);
        void skipTo(const Contact& ct);

    private:
        const RestingRows& m_rows;
        std::size_t m_old = 0, m_dormant = 0;
    };
    PairStart startOf(const double* v, const Contact& ct, double dx, double dy, double s, double warm, double wa,
                      double wb, const SubStepContext& c) const;
    static constexpr std::size_t kPrefetchPairs = 16; // how far ahead buildPairRows asks for ball b's lines
    // Marks of a pair from the first loop: its balls overlap; ball a's, ball
    // b's island needs the solver.
    enum PairMark : unsigned char { kOverlaps = 1, kNeedyA = 2, kNeedyB = 4 };
    // The first loop's lists for one run of pairs (classifyPairs).
    struct PairRun {
        std::vector<PairStart> starts;     // per pair that rests or meets, in pair order
        std::vector<Contact> dormantBalls; // the pairs of two sleepers, in pair order
        std::vector<double> dormantImpulse;
    };
    // From kParallelPairs pairs on, the first loop runs in kPairRuns runs on
    // every core (a fixed cut, so the same work on any thread count).
    static constexpr std::size_t kParallelPairs = 16384;
    static constexpr std::size_t kPairRuns = 16;
    void classifyPairs(const BallState& balls, const SubStepContext& c, const std::vector<Contact>& pairs,
                       std::size_t begin, std::size_t end, PairRun& run);
    std::vector<unsigned char> m_pairKind; // per pair: its PairKind
    std::vector<unsigned char> m_pairMark; // per pair: its PairMark bits
    std::vector<PairStart> m_pairStart;    // per pair that rests or meets, in pair order
    std::vector<PairRun> m_pairRuns;
    ContactIslands m_islands;
    std::vector<int> m_attached; // balls whose islands a pair that does not meet brings into the solve
    std::vector<PairRow> m_spareRows;
    std::vector<Contact> m_rowBalls, m_spareBalls;
    std::vector<double> m_spareImpulse, m_spareVn0;
    std::vector<WallRow> m_spareWalls;
    std::vector<unsigned char> m_held;       // per ball: an impulse touched it in the last solve
    // Ball i was held in the last solve. m_held is shorter than the balls
    // before the first solve and after balls were added (writeBack sizes it).
    bool wasHeld(std::size_t i) const { return i < m_held.size() && m_held[i] != 0; }
    const unsigned char* m_asleep = nullptr; // per ball, this solve: it sleeps (nullptr: none does)
    const double* m_ownRestitution = nullptr; // per ball, this solve: SubStepContext::ownRestitution
    // The pairs of two sleepers, not solved, in (a, b) order, with the
    // impulse they had when their second ball fell asleep: their warm start
    // when they wake.
    std::vector<Contact> m_dormantBalls, m_spareDormantBalls;
    std::vector<double> m_dormantImpulse, m_spareDormantImpulse;
    double m_startShift[2] = {0.0, 0.0}; // this solve, px: startLag·g·h² along x and y
    int m_warmCount = -1;
};

} // namespace forcelab::sim
