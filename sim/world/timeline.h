#pragma once
// A world's past, for stepping back and scrubbing: copies of the world
// (checkpoints) every K steps, and between them the inputs from outside that
// the steps used (where the pointer was, new settings). A World is a value:
// a copy holds everything a step reads (the integrator's kept acceleration
// and IAS15's predictor, the collision system's warm starts and sleepers, the
// random generators, the time and its compensation carry), so a copy stepped
// with the same inputs gives the same bits as the original. To show step s,
// the timeline copies the last checkpoint at or before s and steps it forward
// with the logged inputs: the world it gives back is, bit for bit, the world
// the owner had at step s (positions, velocities, time(), stepCount()).
//
// The owner tells the timeline about everything it does to its world:
//
//   start(w)          a new scene or a reset: the past is forgotten
//   afterStep(w)      after every step the owner takes itself (w.step())
//   settingsEdited(w) after w.setSettings(...) between steps
//   edited(w)         after any other change between steps (balls moved by
//                     hand, a respawn): a checkpoint of w is taken
//
// Pointer moves (w.setPointer) need no call: afterStep sees them through
// World::pointerChanges(). An edit at a step before the latest recorded one
// ends that history: the steps after it are put aside as a cut, which
// restoreCut brings back when the edit is undone.
//
// Memory: a checkpoint costs about worldBytes(balls); the interval K is
// chosen so that the checkpoints of the last kCoverSeconds of simulated time
// fit the budget with kForcedReserve of it left for edits; past the budget
// the oldest cut goes first, then the oldest checkpoint (and the inputs
// before the next one). With the default budget of 256 MiB a 2,000-ball
// world is estimated at 4.2 MB a checkpoint (worldBytes(2000) = 4,161,536 B;
// a copy measured 2.5 MB), 63 fit, K = 67 steps at dt = 1/60 s, and the
// timeline covers 3,618 steps = 60.30 s (plan(2000, 1/60).coveredSeconds);
// a seek then re-runs at most 66 steps. The cover holds while the last 60 s
// have at most kForcedReserve checkpoints made by edited() (settings edits
// and pointer moves cost none).

#include "sim/world/world.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace forcelab::sim {

class Timeline {
public:
    /// bytes, the default memory budget of the checkpoints, logs and cuts
    static constexpr std::size_t kDefaultBudget = std::size_t{256} << 20;
    /// s of simulated time the timeline always covers (at the budget, up to kCoverBalls balls)
    static constexpr double kCoverSeconds = 60.0;
    /// balls of the largest world the cover is promised for
    static constexpr int kCoverBalls = 2000;
    /// checkpoints of the budget kept free for the ones edits force
    static constexpr int kForcedReserve = 8;
    /// bytes, estimated size of a world without balls (settings, scratch, caches)
    static constexpr std::size_t kWorldFixedBytes = std::size_t{64} << 10;
    /// bytes per ball of a world's copy: state, integrator stages, IAS15's 46
    /// 2×N matrices, collision scratch. An upper bound: test_timeline measures
    /// a 2,000-ball resting pile that ran rk4, rk45 and ias15 (about 1,300 B a ball)
    static constexpr std::size_t kWorldBytesPerBall = 2048;

    /// bytes, the estimated size of one copy of a world of `balls` balls
    static std::size_t worldBytes(int balls);

    /// How the budget is spent for a world of `balls` balls stepping by `dt`.
    struct Plan {
        std::size_t worldBytes = 0;   ///< bytes per checkpoint
        int maxCheckpoints = 0;       ///< checkpoints the budget holds (1 at least)
        std::int64_t interval = 1;    ///< steps between two regular checkpoints (K)
        std::int64_t coveredSteps = 0; ///< steps covered by the regular checkpoints the budget holds, reserve left
        double coveredSeconds = 0.0;  ///< s, coveredSteps × dt
    };
    static Plan plan(int balls, double dt, std::size_t budget = kDefaultBudget,
                     double coverSeconds = kCoverSeconds);

    /// `budget` in bytes; `coverSeconds` (s) the span the interval is chosen for.
    explicit Timeline(std::size_t budget = kDefaultBudget, double coverSeconds = kCoverSeconds);

    /// Forgets the past and every cut; `world` is the first checkpoint.
    void start(const World& world);
    /// After the owner's world took a step by itself (not by seek or
    /// replayStep). A step taken behind the latest recorded one ends that
    /// history (put aside as a cut). A step that did not advance (the world
    /// halted, taking the step back) is recorded as a checkpoint.
    void afterStep(const World& after);
    /// After new settings were pushed to `now` between steps: logged as an
    /// input of the next step (no checkpoint). Cuts the future beyond now.
    void settingsEdited(const World& now);
    /// After any other change to `now` between steps: a checkpoint of `now`.
    /// Cuts the future beyond now.
    void edited(const World& now);

    /// The id of the cut the last edit made, or -1 when it cut nothing (it was
    /// made at the latest step) or the cut was dropped or restored since.
    int lastCut() const { return m_lastCut; }
    /// Whether cut `id` is still kept.
    bool hasCut(int id) const;
    /// Brings cut `id` back: `world` becomes the world at the cut's step as it
    /// was before the edit, and the steps recorded then after it are the
    /// future again. What had been recorded after that step since is put aside
    /// as a new cut (lastCut(), for a redo; it holds the undo's own change at
    /// its last step too). Call it after undoing the edit's own change (the
    /// timeline does not know the edit), for the last edit made. False
    /// (nothing changes) when the cut is gone or its step is no longer in the
    /// recorded past.
    bool restoreCut(int id, World& world);

    std::int64_t earliestStep() const;
    std::int64_t latestStep() const { return m_latest; }
    /// s, simulated time of the earliest and latest recorded steps
    double earliestTime() const;
    double latestTime() const { return m_latestTime; }

    /// Makes `world` the recorded world at `step` in [earliestStep(), latestStep()]
    /// (as it was just before it took that step: the inputs logged for it
    /// applied). Starts from `world` itself when it is on the record at or
    /// before `step`, else from the nearest checkpoint at or before `step`,
    /// and re-runs the steps in between. Never changes the record. False
    /// (world untouched) when `step` is outside the record.
    bool seek(std::int64_t step, World& world);
    /// seek(world.stepCount() - 1, world)
    bool stepBack(World& world);
    /// Re-runs the recorded step after `world`'s (world must be on the
    /// record); false at the latest step.
    bool replayStep(World& world);

    /// bytes, the estimated memory held now (checkpoints, logs, cuts)
    std::size_t bytes() const { return m_bytes; }
    std::size_t budget() const { return m_budget; }
    int checkpointCount() const { return static_cast<int>(m_checkpoints.size()); }
    int cutCount() const { return static_cast<int>(m_cuts.size()); }

private:
    /// What came from outside between step k − 1 and step k.
    struct Input {
        std::optional<PointerInput> pointer;                // changed (maybe back): the value it ended at
        std::shared_ptr<const WorldSettings> settings;      // pushed (the last push), or null
    };
    struct Cut {
        int id = 0;
        std::int64_t step = 0;                   // the edit's step
        std::unique_ptr<World> base;             // the world at `step` before the edit, its inputs unapplied
        std::map<std::int64_t, World> checkpoints; // after `step`
        std::map<std::int64_t, Input> inputs;      // at `step` and after
        std::int64_t latest = 0;
        double latestTime = 0.0;                 // s
        std::size_t bytes = 0;
    };

    static void apply(const Input& input, World& world);
    void applyInputsAt(std::int64_t step, World& world) const;
    bool replayFrom(World& world, std::int64_t to);
    /// Puts what lies after `step` aside as a cut (with `base`); -1 when nothing does.
    int cutAfter(std::int64_t step, std::unique_ptr<World> base);
    std::unique_ptr<World> recordedBeforeInputs(std::int64_t step);
    void addCheckpoint(const World& world);
    void setCursor(const World& world);
    bool onCursor(const World& world) const;
    void trim();
    static std::size_t inputBytes(const Input& input);
    void countInput(const Input& input, int sign);

    std::size_t m_budget;
    double m_coverSeconds; // s
    std::map<std::int64_t, World> m_checkpoints; // step → the world just after it reached that step (or an edit there)
    std::map<std::int64_t, Input> m_inputs;      // step k → inputs applied before step k
    std::vector<Cut> m_cuts;                     // oldest first
    int m_nextCut = 0;
    int m_lastCut = -1;
    std::int64_t m_latest = 0;
    double m_latestTime = 0.0;           // s
    std::int64_t m_lastCheckpoint = 0;   // step of the last regular or forced checkpoint
    std::uint64_t m_seenPointerChanges = 0; // the owner's world's World::pointerChanges() when last seen
    std::size_t m_bytes = 0;
    // The owner's world as the timeline last left it: at this step, with its inputs applied.
    bool m_cursorValid = false;
    std::int64_t m_cursorStep = 0;
    std::uint64_t m_cursorPointerChanges = 0;
};

} // namespace forcelab::sim
