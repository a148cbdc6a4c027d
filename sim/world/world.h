#pragma once
// A world: balls, the settings that act on them, and the step that moves them.

#include "sim/world/ball_state.h"
#include "sim/forces/close_pass.h"
#include "sim/collision/collision_system.h"
#include "sim/world/error.h"
#include "sim/forces/force_model.h"
#include "sim/integrators/integrators.h"
#include "sim/world/scene.h"
#include "sim/world/world_settings.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace forcelab::sim {

struct Energy {
    double kinetic = 0.0;   ///< ½ Σ m v²
    double potential = 0.0; ///< uniform gravity, mutual gravity, springs, homing, point force
    double total() const { return kinetic + potential; }
};

/// Counters of one step (all of its sub-steps).
struct StepStats {
    std::int64_t forceEvaluations = 0; ///< calls of the force model (each evaluates all balls)
    std::int64_t wallHits = 0;         ///< ball–wall bounces
    std::int64_t pairsTested = 0;      ///< narrow-phase distance tests
    std::int64_t contacts = 0;         ///< ball–ball contacts found
    std::int64_t acceptedSteps = 0;    ///< rk45 and ias15 only
    std::int64_t rejectedSteps = 0;    ///< rk45 and ias15 only
    std::int64_t roundingChecks = 0;   ///< ias15: force evaluations spent measuring its rounding floor
    /// ias15: the largest rounding floor it worked to instead of a tolerance
    /// below it (1, like time.tolerance; 0 when the tolerance held)
    double toleranceFloor = 0.0;
    double seconds = 0.0;              ///< wall-clock time of the step
    StepStats& operator+=(const StepStats& o);
};

class World {
public:
    World();
    /// A world running `scene`. An invalid scene is refused: it throws
    /// InvalidInput naming the field (reset() returns the problem instead).
    explicit World(const Scene& scene);

    /// Replaces settings and balls and restarts time at 0. Returns the first
    /// problem (and changes nothing) when the scene is invalid.
    std::optional<Error> reset(const Scene& scene);

    /// Pushes new settings between steps. An invalid set is refused whole: the
    /// world keeps its settings and the error names the field.
    std::optional<Error> setSettings(const WorldSettings& settings);
    const WorldSettings& settings() const { return m_settings; }

    const BallState& balls() const { return m_balls; }
    /// Direct access for tools that move balls (drag-and-throw, tests).
    BallState& mutableBalls();

    void setPointer(const PointerInput& pointer);
    const PointerInput& pointer() const { return m_inputs.pointer; }
    /// How many times setPointer changed the pointer (1 each). A change, even
    /// one undone before the next step, makes the integrator start afresh, so
    /// a replay must know it happened, not only where the pointer ended
    /// (sim/world/timeline.h). Not part of the state: a replay may count differently.
    std::uint64_t pointerChanges() const { return m_pointerChanges; }

    /// Advances the world by settings().time.dt, unless it is halted.
    void step();

    /// Set when the world has stopped itself because the motion blows up: why,
    /// in plain words, with the fix. step() does nothing while it is set. New
    /// settings (setSettings) or a reset clear it if the cause is gone.
    const std::optional<std::string>& halted() const { return m_halted; }

    /// s, the time the state is at: the sum of the steps taken, rounded once
    /// (not once a step), so after millions of steps it is still the time
    /// the integrator moved the balls to.
    double time() const { return m_time; }
    std::int64_t stepCount() const { return m_stepCount; }
    /// s, what the rounding of time()'s sum lost so far (Kahan's carry).
    double timeCarry() const { return m_timeCarry; }
    /// The spawn settings the world was started with.
    const SpawnSettings& spawn() const { return m_spawn; }

    /// The random generators where the run has got to: the random
    /// acceleration's, spawning's and the wind's, so a copy of the run written
    /// elsewhere (the course's JavaScript) can go on from this step and draw
    /// the same numbers.
    const std::mt19937_64& accelGenerator() const { return m_rng; }
    const std::mt19937_64& spawnGenerator() const { return m_spawnRng; }
    const WindGenerator& windGenerator() const { return m_inputs.wind; }
    const StepStats& lastStep() const { return m_last; }
    const StepStats& totals() const { return m_totals; }

    Energy energy() const;
    Vec2 momentum() const;          ///< Σ m v
    double angularMomentum() const; ///< Σ m (x × v) about the origin, z component

    /// Energy and momentum accounting, for judging an integrator: with it on,
    /// every change made on purpose is booked — the work of drag, wind, the
    /// random acceleration, the pointer and a clamped point force (trapezoid
    /// rule over each sub-step), what walls, the speed limit and collisions
    /// change, and any edit between steps (settings, balls, spawning). What is
    /// left, energyDrift(), is the integrator's own error (plus the booking's,
    /// which is second order in dt). Off by default: it costs four extra force
    /// evaluations and two energy sums per sub-step. Switching it on starts
    /// the books at the current state; a reset restarts them.
    void setAccounting(bool on);
    bool accounting() const { return m_accounting; }
    double startEnergy() const { return m_books.startEnergy; }   ///< total energy when the books started
    double bookedEnergy() const { return m_books.bookedEnergy; } ///< added (+) or removed (−) on purpose since
    double energyDrift() const;   ///< E_now − E_start − booked
    Vec2 momentumDrift() const;   ///< p_now − p_start − impulse of every force but mutual gravity and collisions

    /// Acceleration of every ball in the current state (for the readout).
    Matrix2X accelerations() const;

    /// Ball i's acceleration from each model that is on, in the order the
    /// step adds them (sim/forces/force_models.h), with the step's own inputs
    /// (wind, random values, pointer). They add up to accelerations().col(i).
    struct SourceAcceleration {
        std::string_view model;
        Vec2 acceleration; ///< px/s²
    };
    std::vector<SourceAcceleration> accelerationBySource(int i) const;
    /// The wind acting now on a reference ball, px/s² (+ blows right).
    double wind() const;
    /// The random acceleration drawn for the last step, px/s², 2×N (empty
    /// until a step with models.random_accel on has drawn it).
    const Matrix2X& randomDraws() const { return m_inputs.randomAccel; }
    /// The comparison wind (settings().wind.compare), px/s²; it acts on nothing.
    double compareWind() const;
    const std::vector<Contact>& contacts() const { return m_collisions.contacts(); }
    /// The collision stage itself, for its per-stage profile (bench --profile) and tuning.
    CollisionSystem& collisionSystem() { return m_collisions; }
    const CollisionSystem& collisionSystem() const { return m_collisions; }

private:
    void subStep(double h);
    void stepAsleep(int substeps, std::chrono::steady_clock::time_point started);
    void finishStep(std::chrono::steady_clock::time_point started);
    void holdPinned();
    void advanceTime(double dt);
    void drawStepRandomness();
    void spawnOverTime();
    bool blewUp() const;
    std::string explainBlowUp(double subStep, const std::optional<std::string>& unresolved) const;
    std::string explainSingularApproach(double subStep) const;

    WorldSettings m_settings;
    BallState m_balls;
    StepInputs m_inputs;
    Integrator m_integrator;
    CollisionSystem m_collisions;
    SpawnSettings m_spawn;
    std::mt19937_64 m_rng;      // wind-independent draws: random acceleration
    std::mt19937_64 m_spawnRng; // spawning over time
    double m_time = 0.0;    // s, at the start of the current step
    double m_timeCarry = 0.0; // s, what the rounding of m_time's sum lost (compensated summation)
    double m_subTime = 0.0; // s, time into the current step covered by its sub-steps
    bool m_gaveUp = false;  // an adaptive integrator gave up in this step
    double m_stuckSubStep = 0.0; // s, > 0 when it gave up because even a sub-step this short missed the tolerance
    std::int64_t m_stepCount = 0;
    std::uint64_t m_pointerChanges = 0; // see pointerChanges()
    StepStats m_last;
    StepStats m_totals;
    // The books of the accounting (see setAccounting).
    struct Books {
        double startEnergy = 0.0;
        double bookedEnergy = 0.0;
        double lastEnergy = 0.0; // at the end of the last step: what an edit between steps changed
        Vec2 startMomentum = Vec2::Zero();
        Vec2 bookedMomentum = Vec2::Zero();
        Vec2 lastMomentum = Vec2::Zero();
    };
    void startBooks();
    void bookEditsSinceLastStep();
    void closeBooks();
    bool m_accounting = false;
    Books m_books;

    std::optional<std::string> m_halted;
    Matrix2X m_savedPosition; // state before the step, to undo a step that blew up
    Matrix2X m_savedVelocity;
    Matrix2X m_startPosition; // scratch: state at the start of a sub-step
    Matrix2X m_startVelocity;
    // The pinned balls and where they are, taken at the start of each step
    // (a tool may have moved one between steps); empty in most scenes.
    std::vector<int> m_pinnedIndex;
    Matrix2X m_pinnedPosition;
};


/// Checks the spawn settings ("spawn.count: …").
std::optional<Error> validateSpawn(const SpawnSettings& spawn);

/// Checks listed balls: finite position and velocity, radius in
/// [kMinRadius, kMaxRadius], an explicit mass in [kMinMass, kMaxMass], an
/// own restitution in [0, 1] ("balls.3.r: …").
std::optional<Error> validateBalls(std::span<const Ball> balls);

/// Checks a full settings struct. Returns the first problem, with the lesson
/// file's key path of the field ("models.drag.k") and what is wrong.
std::optional<Error> validateSettings(const WorldSettings& settings);

/// Settings, spawn and listed balls together: the first problem, or nullopt.
std::optional<Error> validateScene(const Scene& scene);

} // namespace forcelab::sim
