#pragma once
// Ball–ball collisions: a broad phase (brute, halved, sweep or grid) that
// finds every pair of touching balls, and a response that marks them (flag)
// or changes their velocities. The world calls step() once per sub-step, and
// only when the scene's response is not None.
//
// Touching means strictly overlapping: distance < r_a + r_b (see
// narrow_phase.h). Every detector reports the same pairs, sorted by (a, b),
// and the response walks them in that order, so the result of a step does not
// depend on the detector, only its cost does.

#include "sim/world/ball_state.h"
#include "sim/world/world_settings.h"
#include "sim/collision/broad_phase/broad_phase_input.h"
#include "collision_profile.h"
#include "contact.h"
#include "sim/collision/resting/contact_solver.h"
#include "sim/collision/broad_phase/contact_sort.h"
#include "sim/collision/response/impact_events.h"
#include "sim/collision/resting/resting_solver.h"
#include "sim/collision/resting/sleep.h"
#include "sim/collision/resting/speculative_margin.h"
#include "sim/collision/resting/sub_step_context.h"
#include "sim/collision/broad_phase/sweep_and_prune.h"
#include "sim/collision/broad_phase/uniform_grid.h"

#include <vector>

namespace forcelab::sim {

class CollisionSystem {
public:
    /// Detects and responds. `startPositions` are the positions at the start of
    /// the (sub-)step of length dt, for continuous detection (used only when
    /// settings.continuous is on and it has one column per ball). Sets
    /// balls.colliding. Returns this call's counters.
    ///
    /// Per contact, in (a, b) order: the response model changes the velocities
    /// along the line of centres at detection time (pairs already moving apart
    /// are skipped), then positional correction pushes the pair apart if it
    /// still overlaps. `flag` only marks.
    ///
    /// Continuous mode (any response but flag) makes every impact inside the
    /// step at its moment, in time order (impact_events.h): each ball follows
    /// the path `motion` describes, and with the exact wall model the walls
    /// are impacts too (the caller must not have applied them: see
    /// wallsInTimeOrder). Pairs that still overlap at the end (they began the
    /// step overlapping, or the impact limit was reached) get the discrete
    /// pass above.
    ///
    /// `gravity` (px/s², zero when gravity is off) switches on resting contact
    /// for 2d-impulse (see contact_solver.h): a restitution threshold, several
    /// velocity passes with the walls taking part, and positional correction
    /// with slop. Without gravity the step is the one pass described above.
    CollisionStats step(BallState& balls, const Matrix2X& startPositions, const CollisionSettings& settings,
                        const BoxSettings& box, const WallSettings& walls, double dt,
                        const Vec2& gravity = Vec2::Zero(), const StepMotion& motion = StepMotion{});

    /// Whether step() bounces the balls off the walls itself, in time order
    /// with the ball–ball impacts (continuous detection with a response and the
    /// exact wall model): the world's wall stage must then leave them alone.
    static bool wallsInTimeOrder(const CollisionSettings& settings, const WallSettings& walls);
    /// Whether the last step() reached the impact limit of continuous detection
    /// (ImpactEvents::eventLimit) and resolved the rest of its step discretely.
    bool lastImpactLimitReached() const { return m_lastLimitReached; }

    /// Tuning of the resting-contact solver (tests, bench).
    void setSolverSettings(const ContactSolverSettings& s) { m_solver = s; }
    const ContactSolverSettings& solverSettings() const { return m_solver; }
    /// Velocity passes the last step() made (0 when it had no resting-contact solve).
    int lastVelocityPasses() const { return m_lastPasses; }
    /// Rows that alone got the extra passes of a bounce in the last step()
    /// (the rows near it; 0: no bounce, or every row got them).
    std::size_t lastBounceRegionRows() const { return m_lastBounceRows; }
    /// Whether the last step()'s staged solve had a pair or a wall bounce.
    bool lastStepBounced() const { return m_lastBounced; }

    /// Whether balls at rest may sleep (contact_solver.h, point 7): the
    /// world allows it while every force on a ball at rest depends on where
    /// it is alone. Off by default; switching it off wakes every ball.
    void allowSleep(bool on);
    /// Whether every force acting gives every ball the same acceleration
    /// (gravity alone): then a group of balls with no wall, sleeper or
    /// pinned ball among them falls as one, and its contacts are impacts,
    /// not resting contacts (contact_solver.h, point 8). Off by default:
    /// every slow contact rests.
    void setSameForceOnEveryBall(bool on) { m_sameForce = on; }
    /// Wakes every sleeping ball (an edit between steps).
    void wakeAll() { m_sleep.wakeAll(); }
    /// Balls asleep now, and per ball whether it sleeps (nullptr: none).
    int sleepingCount() const { return m_sleep.count(); }
    const unsigned char* sleeping() const { return m_sleep.asleep(); }
    /// Per ball, whether a row of the last resting solve pushed it (the
    /// balls the staged solve moved; a free island's balls are not among
    /// them: free_impacts.h). Empty before the first resting solve.
    const std::vector<unsigned char>& lastHeld() const { return m_resting.held(); }
    /// Balls that a pair approaching woke in the last step().
    int lastWoken() const { return m_sleep.lastWoken(); }

    /// Whether step() with these arguments would leave all `n` balls as they
    /// are: it would take the sleeping path, and every ball slept through
    /// the whole of the last step() (its sleepers were put back where they
    /// fell asleep at speed 0, no pair woke one, and its pairs were found
    /// where they are now). The world then calls stayAsleep() instead.
    bool everyBallSleeps(const CollisionSettings& settings, int n, const Vec2& gravity, double dt) const;
    /// The step of a world whose every ball sleeps (everyBallSleeps): no
    /// detection and no solve, and nothing changes but the counters of the
    /// last step (no passes, no bounce, no ball woken). contacts() and the
    /// balls' flags stay those of the last step, found at these same
    /// positions. Returns this call's counters: the touching pairs, none tested.
    CollisionStats stayAsleep();

    /// Detection alone: every touching pair (distance < r_a + r_b), sorted by
    /// (a, b) and identical for every method.
    CollisionStats detect(const BallState& balls, Detection method, std::vector<Contact>& out);

    /// Continuous detection alone: every pair that touches at the end or whose
    /// straight paths from `startPositions` meet during the step, sorted by (a, b).
    CollisionStats detectMoving(const BallState& balls, const Matrix2X& startPositions, Detection method,
                                std::vector<Contact>& out);

    /// The touching pairs found by the last step(), sorted by (a, b).
    const std::vector<Contact>& contacts() const { return m_contacts; }

    /// Per-stage timing (bench --profile): off by default, then no clock is read.
    void setProfiling(bool on) { m_profiling = on; }
    const CollisionProfile& profile() const { return m_profile; }
    void resetProfile() { m_profile = CollisionProfile{}; }

    /// The broad phases, for counters and tuning (bench, tests).
    const SweepAndPrune& sweepAndPrune() const { return m_sweep; }
    UniformGrid& grid() { return m_grid; }
    const UniformGrid& grid() const { return m_grid; }

private:
    // The paths a step can take, chosen once per step by planStep.
    enum class StepPath {
        Nothing,     // response None: no detection
        InTimeOrder, // continuous detection with a response (impact_events.h)
        Speculative, // resting contact on speculative contacts, maybe with sleep
        Flag,        // the touching pairs marked, nothing else
        Resting,     // resting contact on the touching pairs
        OnePass,     // one pass of the response, then positional correction
    };
    struct StepPlan {
        StepPath path = StepPath::Nothing;
        bool swept = false;        // detection on the paths from the start positions
        bool sleeping = false;     // balls at rest may sleep (Speculative only)
        double restingSpeed = 0.0; // px/s, v_rest of the resting paths
    };
    void beginStep();
    StepPlan planStep(const CollisionSettings& settings, bool continuous, const Vec2& gravity, double dt) const;
    void stepSpeculative(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                         const WallSettings& walls, double dt, const Vec2& gravity, const StepMotion& motion,
                         const StepPlan& plan, CollisionStats& stats, StageClock& clock);
    void detectTouching(BallState& balls, const Matrix2X* startPositions, const CollisionSettings& settings,
                        CollisionStats& stats, StageClock& clock);
    void stepFlag(BallState& balls, const Matrix2X& startPositions, const CollisionSettings& settings,
                  const StepPlan& plan, CollisionStats& stats, StageClock& clock);
    void stepResting(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                     const WallSettings& walls, double dt, const Vec2& gravity, const StepMotion& motion,
                     const StepPlan& plan, CollisionStats& stats, StageClock& clock);
    void stepOnePass(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                     const WallSettings& walls, CollisionStats& stats, StageClock& clock);
    void noteRestingSolve();
    void findContacts(Detection method, bool swept, std::vector<Contact>& out, CollisionStats& stats,
                      StageClock& clock);
    void resolve(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                 const WallSettings& walls);
    CollisionStats stepInTimeOrder(BallState& balls, const Matrix2X& startPositions,
                                   const CollisionSettings& settings, const BoxSettings& box,
                                   const WallSettings& walls, double dt, const StepMotion& motion, StageClock& clock);
    SubStepContext subStep(const CollisionSettings& settings, const BoxSettings& box, const WallSettings& walls,
                           double h, double restingSpeed, const Vec2& gravity, const StepMotion& motion,
                           const BallState& balls) const;

    RestingSolver m_resting;
    SleepingBalls m_sleep;
    bool m_sleepAllowed = false;
    bool m_sameForce = false; // setSameForceOnEveryBall
    bool m_sleptThrough = false; // the last step() began and ended with every ball asleep, none woken
    SpeculativeMargin m_margin;
    std::vector<double> m_grow;          // per ball: how much its radius grows for speculative contacts
    std::vector<Contact> m_speculative;  // touching and speculative pairs, sorted by (a, b)
    ContactSolverSettings m_solver;
    int m_lastPasses = 0;
    std::size_t m_lastBounceRows = 0;
    bool m_lastBounced = false;
    bool m_profiling = false;
    CollisionProfile m_profile;

    std::vector<Contact> m_contacts;
    // Scratch kept between steps: no allocation once sizes settle, and the
    // sweep keeps its order.
    BroadPhaseInput m_input;
    SweepAndPrune m_sweep;
    UniformGrid m_grid;
    ContactSorter m_sorter;
    Matrix2X m_detected;                 // positions at detection time
    ImpactEvents m_events;               // continuous: every impact of the step in time order
    std::vector<Contact> m_met;          // continuous: pairs that met during the step
    std::vector<Contact> m_candidates;   // continuous: pairs whose paths may meet
    bool m_lastLimitReached = false;
};

} // namespace forcelab::sim
