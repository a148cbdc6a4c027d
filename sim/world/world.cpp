#include "sim/world/world.h"

#include "sim/forces/custom_force.h"

#include "sim/forces/close_pass.h"
#include "sim/forces/force_models.h"
#include "sim/integrators/integrator_info.h"
#include "sim/world/names.h"
#include "sim/world/number_text.h"
#include "sim/world/parameters.h"
#include "sim/integrators/stability.h"
#include "sim/world/walls.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace forcelab::sim {

StepStats& StepStats::operator+=(const StepStats& o)
{
    forceEvaluations += o.forceEvaluations;
    wallHits += o.wallHits;
    pairsTested += o.pairsTested;
    contacts += o.contacts;
    acceptedSteps += o.acceptedSteps;
    rejectedSteps += o.rejectedSteps;
    roundingChecks += o.roundingChecks;
    toleranceFloor = std::max(toleranceFloor, o.toleranceFloor);
    seconds += o.seconds;
    return *this;
}

// ---------------------------------------------------------------------------
// Validation: every field is checked with the key path of the lesson format,
// so the loader, the CLI and the UI all report a problem the same way.

namespace {

class Checker {
public:
    void finite(const char* key, double v)
    {
        if (!m_error && !std::isfinite(v))
            fail(key, "must be a finite number");
    }
    void range(const char* key, double v, double lo, double hi, bool loOpen = false)
    {
        if (m_error)
            return;
        if (!std::isfinite(v) || v > hi || (loOpen ? v <= lo : v < lo)) {
            fail(key, numberText(v) + " is outside " + rangeText(lo, hi, {}, loOpen));
        }
    }
    void fail(const char* key, const std::string& what)
    {
        if (!m_error)
            m_error = keyError(key, what);
    }
    std::optional<Error> result() const { return m_error; }

private:
    std::optional<Error> m_error;
};

} // namespace

std::optional<Error> validateSettings(const WorldSettings& s)
{
    // Every row of the parameter table: its range, whole numbers, choices.
    for (const Parameter& p : parameters())
        if (auto problem = checkValue(p, p.get(s)))
            return keyError(std::string(p.key), *problem);
    // What no single row can say.
    if (s.time.integrator == IntegratorKind::Exact) {
        if (const char* why = nonConstantAccelerationReason(s))
            return keyError("time.integrator", std::string("exact needs a constant acceleration, but ")
                                                   .append(why)
                                                   .append("; pick another integrator or switch that model off"));
    }
    // A student's force law: its formulas compile and its potential fits it.
    // Checked even while it is off, so a law is never kept that cannot run.
    if (auto error = checkCustomForce(s.custom, s.box.width, s.box.height))
        return error;
    return std::nullopt;
}

std::optional<Error> validateSpawn(const SpawnSettings& s)
{
    Checker c;
    c.range("spawn.count", s.count, 0, kMaxBalls);
    c.range("spawn.radius[0]", s.minRadius, kMinRadius, kMaxRadius);
    c.range("spawn.radius[1]", s.maxRadius, s.minRadius, kMaxRadius);
    c.range("spawn.speed[0]", s.minSpeed, 0.0, 1e9);
    c.range("spawn.speed[1]", s.maxSpeed, s.minSpeed, 1e9);
    c.range("spawn.per_step", s.perStep, 0.0, 1.0);
    c.range("spawn.max_count", s.maxCount, 0, kMaxBalls);
    return c.result();
}

// ---------------------------------------------------------------------------

World::World()
{
    reset(Scene{});
}

World::World(const Scene& scene)
{
    if (auto error = validateScene(scene))
        throw InvalidInput(*error);
    reset(scene);
}

std::optional<Error> validateBalls(std::span<const Ball> balls)
{
    Checker c;
    for (std::size_t i = 0; i < balls.size() && !c.result(); ++i) {
        const Ball& b = balls[i];
        const std::string at = "balls." + std::to_string(i) + ".";
        c.finite((at + "x").c_str(), b.position.x());
        c.finite((at + "y").c_str(), b.position.y());
        c.finite((at + "vx").c_str(), b.velocity.x());
        c.finite((at + "vy").c_str(), b.velocity.y());
        c.range((at + "r").c_str(), b.radius, kMinRadius, kMaxRadius);
        if (b.mass != 0.0) // 0: the density-1 sphere of its radius
            c.range((at + "mass").c_str(), b.mass, kMinMass, kMaxMass);
        c.range((at + "q").c_str(), b.charge, -kMaxCharge, kMaxCharge);
        if (b.restitution != kWorldRestitution)
            c.range((at + "restitution").c_str(), b.restitution, 0.0, 1.0);
    }
    return c.result();
}

std::optional<Error> validateScene(const Scene& scene)
{
    if (auto error = validateSettings(scene.settings))
        return error;
    if (auto error = validateSpawn(scene.spawn))
        return error;
    return validateBalls(scene.balls);
}

std::optional<Error> World::reset(const Scene& scene)
{
    if (auto error = validateScene(scene))
        return error;
    m_settings = scene.settings;
    m_balls = buildBalls(scene);
    m_spawn = scene.spawn;
    m_inputs = StepInputs{};
    m_inputs.wind = WindGenerator(m_settings.time.seed);
    m_inputs.compareWind = WindGenerator(m_settings.time.seed);
    m_rng.seed(m_settings.time.seed);
    m_spawnRng.seed(m_spawn.seed ^ 0x5bd1e995u); // its own stream: spawning does not shift the wind
    m_integrator.invalidate();
    m_collisions.wakeAll();
    m_time = 0.0;
    m_timeCarry = 0.0;
    m_stepCount = 0;
    m_last = StepStats{};
    m_totals = StepStats{};
    m_halted = stabilityProblem(m_settings, m_balls);
    if (m_accounting)
        startBooks();
    return std::nullopt;
}

std::optional<Error> World::setSettings(const WorldSettings& settings)
{
    if (auto error = validateSettings(settings))
        return error;
    m_settings = settings;
    m_integrator.invalidate();
    m_collisions.wakeAll(); // a sleeping pile must feel the new settings
    m_halted = stabilityProblem(m_settings, m_balls);
    return std::nullopt;
}

BallState& World::mutableBalls()
{
    m_integrator.invalidate();
    m_collisions.wakeAll(); // a moved ball may have held up a sleeping one
    return m_balls;
}

void World::setPointer(const PointerInput& pointer)
{
    if (pointer == m_inputs.pointer)
        return;
    m_inputs.pointer = pointer;
    ++m_pointerChanges;
    m_integrator.invalidate();
}

// Random values are drawn once per step, before any force is evaluated, so
// every stage of a multi-stage integrator sees the same values and a run with
// the same seed is the same run.
void World::drawStepRandomness()
{
    const WorldSettings& s = m_settings;
    m_inputs.wind.advance(s.wind.mode, s.wind, m_inputs.pointer, s.box.width);
    if (s.wind.compare != WindMode::Off)
        m_inputs.compareWind.advance(s.wind.compare, s.wind, m_inputs.pointer, s.box.width);
    if (s.randomAccel.enabled) {
        // Each component uniform in [−strength, strength): centred on zero, so
        // on average it pushes nowhere. The fixed kind draws once per ball.
        // The un-centred bug takes the same u in [0, 1) as strength·u instead
        // of strength·(2u − 1) (both exact in binary), so one seed gives the
        // same draws with and without the bug.
        Matrix2X& a = m_inputs.randomAccel;
        const Eigen::Index from = s.randomAccel.fixed ? std::min(a.cols(), Eigen::Index(m_balls.size())) : 0;
        a.conservativeResize(2, m_balls.size());
        for (Eigen::Index i = from; i < a.cols(); ++i)
            for (int d = 0; d < 2; ++d) {
                const double u = static_cast<double>(m_rng() >> 11) * 0x1.0p-53;
                a(d, i) = s.randomAccel.strength * (s.randomAccel.uncentred ? u : 2.0 * u - 1.0);
            }
    }
    // The step's inputs changed: Verlet's kept acceleration is stale.
    if (s.wind.mode != WindMode::Off || s.randomAccel.enabled)
        m_integrator.invalidate();
}

// Spawning over time: with probability perStep one random ball appears, until
// the world holds maxCount balls.
void World::spawnOverTime()
{
    if (m_spawn.perStep <= 0.0 || m_balls.size() >= m_spawn.maxCount)
        return;
    const double u = static_cast<double>(m_spawnRng() >> 11) * 0x1.0p-53;
    if (u >= m_spawn.perStep)
        return;
    m_balls.append(randomBall(m_spawn, m_settings.box, m_spawnRng));
    m_integrator.invalidate();
    if (m_settings.drag.enabled && !m_halted) // a lighter ball may need a shorter step under drag
        m_halted = stabilityProblem(m_settings, m_balls);
}

double World::wind() const
{
    return m_inputs.wind.at(m_settings.wind.mode, m_settings.wind, m_time);
}

double World::compareWind() const
{
    return m_inputs.compareWind.at(m_settings.wind.compare, m_settings.wind, m_time);
}

// Beyond these the state is lost to rounding (px, px/s): far outside any scene
// the workbench can show, far inside what a double holds.
constexpr double kLostPosition = 1e12;
constexpr double kLostSpeed = 1e12;
constexpr double kFollowPairs = 0.5;
bool World::blewUp() const
{
    if (m_balls.empty())
        return false;
    const double far = m_balls.position.cwiseAbs().maxCoeff();
    const double fast = m_balls.velocity.cwiseAbs().maxCoeff();
    return !(far < kLostPosition) || !(fast < kLostSpeed); // also true for NaN
}

std::string World::explainBlowUp(double h, const std::optional<std::string>& unresolved) const
{
    const WorldSettings& s = m_settings;
    const std::string stopped = "the simulation stopped at t = " + roundedText(m_time, 4) + " s, one step before ";
    if (unresolved)
        return stopped + *unresolved;
    if (m_gaveUp && m_stuckSubStep > 0.0)
        return stopped + explainSingularApproach(h);

    const std::string what = m_gaveUp ? std::string(toString(s.time.integrator)) + " needed more than " +
                                            std::to_string(kMaxAdaptiveSubSteps) + " sub-steps for one step"
                                      : std::string("a ball was about to leave every sensible range");
    // Name a close pass only where the state shows one: where the adaptive
    // integrator gave up, or before the step that ran away.
    std::optional<ClosePass> pass;
    if (m_gaveUp) {
        pass = shortestFallTime(s, m_balls, Pulls::PairsAndPoint);
    } else {
        BallState before = m_balls;
        before.position = m_savedPosition;
        before.velocity = m_savedVelocity;
        pass = shortestFallTime(s, before, Pulls::PairsAndPoint);
    }
    const double tooShort = m_gaveUp ? 1e-3 * h : h; // an adaptive integrator follows passes far below h
    if (pass && pass->fallTime < tooShort)
        return stopped + "it blew up (" + what + "): " + describeClosePass(*pass, s, h);
    std::string cause;
    if (s.custom.enabled)
        cause.append(describeCustomLaw(s.custom))
            .append(" grows too fast for this dt, or gives a number that is not finite (a division by zero?): "
                    "check its formulas, or lower dt");
    else if (s.drag.enabled && s.drag.law == DragLaw::Quadratic)
        cause = "quadratic drag is too strong for this dt at these speeds: lower dt or k";
    else if (m_gaveUp)
        cause = "the forces change too fast for this tolerance: raise time.tolerance or lower dt";
    else
        cause = "the forces are too strong for this time step: lower dt or pick rk45";
    return stopped + "it blew up (" + what + "). Likely cause: " + cause;
}

// An adaptive integrator could not hold its tolerance with the shortest
// sub-step it may take: the force changes faster than anything can follow,
// which only happens next to a point where it is singular. m_balls holds the
// state the integrator reached, next to that point.
std::string World::explainSingularApproach(double h) const
{
    const WorldSettings& s = m_settings;
    const std::string what = std::string(toString(s.time.integrator)) + " could not hold its tolerance of " +
                             numberText(s.time.tolerance) + " even with sub-steps of " +
                             roundedText(m_stuckSubStep, 2) + " s";
    // A 1/d² pull the world knows: the pair, or the ball and the point, with
    // the shortest free fall, if it is far below the step.
    if (const auto pass = shortestFallTime(s, m_balls, Pulls::PairsAndPoint); pass && pass->fallTime < 1e-3 * h)
        return "a singular approach (" + what + "): " + describeClosePass(*pass, s, h);
    // Otherwise the ball pulled hardest, and the model that pulls it.
    const Matrix2X a = accelerations();
    int ball = -1;
    double largest = -1.0;
    for (int i = 0; i < m_balls.size(); ++i) {
        const double size = a.col(i).allFinite() ? a.col(i).norm() : std::numeric_limits<double>::infinity();
        if (size > largest) {
            largest = size;
            ball = i;
        }
    }
    std::string where;
    std::string_view model;
    if (ball >= 0) {
        double strongest = -1.0;
        for (const SourceAcceleration& source : accelerationBySource(ball)) {
            const double size = source.acceleration.allFinite() ? source.acceleration.norm()
                                                                : std::numeric_limits<double>::infinity();
            if (size > strongest) {
                strongest = size;
                model = source.model;
            }
        }
        where = ": ball " + std::to_string(ball) + " at (" + roundedText(m_balls.position(0, ball), 6) + ", " +
                roundedText(m_balls.position(1, ball), 6) + ") px is pulled at " + roundedText(largest, 2) + " px/s²";
        if (!model.empty())
            where.append(" by the ").append(model);
    }
    std::string fix;
    if (model == "custom force")
        fix = describeCustomLaw(s.custom) +
              " is singular there, or nearly: keep its denominator away from zero (add a small constant to the "
              "distance squared, as softening does)";
    else
        fix = "the force is singular there, or nearly: soften it, clamp it, or raise time.tolerance";
    return "a singular approach (" + what + ")" + where + ". Fix: " + fix;
}

void World::step()
{
    if (m_halted)
        return;
    // Quadratic drag's stiffness grows with the speed: checked at the balls'
    // speeds before every step, so a step that would turn a ball round (or
    // speed it up) is never taken (k = 0.01 at 10,000 px/s went to −6,667).
    if (m_settings.drag.enabled && m_settings.drag.law == DragLaw::Quadratic)
        if ((m_halted = stabilityProblem(m_settings, m_balls)))
            return;
    const auto started = std::chrono::steady_clock::now();
    m_pinnedIndex.clear();
    if (m_balls.anyPinned()) {
        for (int i = 0; i < m_balls.size(); ++i)
            if (m_balls.pinned[static_cast<std::size_t>(i)])
                m_pinnedIndex.push_back(i);
        m_pinnedPosition.resize(2, static_cast<Eigen::Index>(m_pinnedIndex.size()));
        for (std::size_t k = 0; k < m_pinnedIndex.size(); ++k)
            m_pinnedPosition.col(static_cast<Eigen::Index>(k)) = m_balls.position.col(m_pinnedIndex[k]);
        holdPinned(); // a tool may have given one a velocity between steps
    }
    if (m_accounting)
        bookEditsSinceLastStep();
    const Books booksBefore = m_books; // a step that is undone is taken off the books too
    m_last = StepStats{};
    drawStepRandomness();
    m_subTime = 0.0;
    m_gaveUp = false;
    m_stuckSubStep = 0.0;
    const int substeps = m_settings.time.substeps;
    // The per-frame bug moves the balls by one frame's worth whatever dt is.
    const double h = (m_settings.time.perFrame ? kFrameSeconds : m_settings.time.dt) / substeps;
    // What a fixed step cannot follow is watched for fixed-step integrators
    // only (rk45 and ias15 shorten their own sub-steps), unless the scene
    // asks to see the step's mistake (stage 17's slingshot).
    const bool adaptive = integratorInfo(m_settings.time.integrator).adaptive;
    const bool watch = !adaptive && !m_settings.time.stepPastClosePasses;
    // A ball at rest may sleep only while every force on it at rest stays
    // what it was when it fell asleep; a group of touching balls in mid-air
    // falls as one only while every force gives every ball the same
    // acceleration.
    bool steady = true, same = true;
    for (const ForceModelInfo& model : forceModels()) {
        const bool on = model.on(m_settings);
        steady = steady && (!on || model.steadyAtRest);
        same = same && (!on || model.sameForEveryBall);
    }
    m_collisions.allowSleep(steady); // not steady: every ball wakes, so none sleeps below
    m_collisions.setSameForceOnEveryBall(same);
    if (m_collisions.everyBallSleeps(m_settings.collisions, m_balls.size(), m_settings.gravity.acting(), h)) {
        stepAsleep(substeps, started);
        return;
    }
    // Keep the state so a step that blows up can be taken back. A copy of two
    // 2×N matrices: small next to the step itself.
    m_savedPosition = m_balls.position;
    m_savedVelocity = m_balls.velocity;
    for (int k = 0; k < substeps && !m_gaveUp; ++k)
        subStep(h);
    // A fixed-step integrator does not notice that it skips over a close
    // pass: stop when the pair (or ball and unclamped point) closest in fall
    // time is closer than two sub-steps can follow, or where a custom force
    // is stiffer than the sub-step can follow. A clamped point bounds the
    // pull, and the mistake with it: stage 17 shows that one.
    std::optional<std::string> unresolved;
    if (watch && !m_gaveUp && !blewUp()) {
        if (auto pass = shortestFallTime(m_settings, m_balls, Pulls::PairsAndUnclampedPoint);
            pass && h > kFollowPairs * pass->fallTime)
            unresolved = "a close pass it cannot follow: " + describeClosePass(*pass, m_settings, h);
        else if (m_settings.custom.enabled) {
            BallState before = m_balls;
            before.position = m_savedPosition;
            before.velocity = m_savedVelocity;
            const auto steep =
                steepestCustomForce(m_settings, before, m_time, m_balls, m_time + m_settings.time.dt, h);
            if (steep && !steep->followedBy(h))
                unresolved = "a force it cannot follow: " + describeSteepForce(*steep, m_settings, m_balls, h);
        }
    }
    // A potential may be undefined between the points the load-time check
    // samples: the energy would turn to NaN without a word.
    if (!unresolved && !m_gaveUp && !blewUp()) {
        if (const int k = firstBallWithoutPotential(m_settings, m_balls, m_balls.position); k >= 0) {
            const std::string where = "ball " + std::to_string(k) + " at (" + roundedText(m_balls.position(0, k), 4) +
                                      ", " + roundedText(m_balls.position(1, k), 4) + ") px";
            unresolved = "a place where the potential U of " + describeCustomLaw(m_settings.custom) +
                         " is not a number: " + where + "; a potential must have a value wherever its force does";
        }
    }
    if (m_gaveUp || blewUp() || unresolved) {
        // Undo the step and stop, with the cause found in the state and its fix.
        m_halted = explainBlowUp(h, unresolved);
        m_balls.position = m_savedPosition;
        m_balls.velocity = m_savedVelocity;
        m_books = booksBefore;
        m_integrator.invalidate();
        m_collisions.wakeAll();
        return;
    }
    finishStep(started);
}

// Every ball asleep (CollisionSystem::everyBallSleeps): each sub-step would
// move every ball, put it back where it fell asleep at speed 0 and find the
// same pairs again, so the step is the same to the bit without them. The
// pile costs nothing until an edit, a new ball or a change of settings
// wakes it. The step's random draws (drawStepRandomness) are made as before.
void World::stepAsleep(int substeps, std::chrono::steady_clock::time_point started)
{
    for (int k = 0; k < substeps; ++k)
        m_last.contacts += m_collisions.stayAsleep().contacts;
    m_integrator.invalidate(); // as the sub-steps' contacts would have
    finishStep(started);
}

void World::finishStep(std::chrono::steady_clock::time_point started)
{
    spawnOverTime(); // a new ball's energy and momentum are booked with the edits, at the next step
    ++m_stepCount;
    advanceTime(m_settings.time.dt);
    if (m_accounting)
        closeBooks();
    m_last.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    m_totals += m_last;
}

// m_time += dt with Kahan's compensation. Added plainly, each step rounds the
// sum by up to half an ulp of m_time, and with dt = 0.001 s the errors do not
// cancel: after 6.3 million steps the time was 8e-7 s ahead of the state,
// which the integrator had moved by exactly the steps' dt's. The carry keeps
// the lost bits, so the time stays the rounded sum of the steps.
void World::advanceTime(double dt)
{
    const double y = dt - m_timeCarry;
    const double sum = m_time + y;
    m_timeCarry = (sum - m_time) - y;
    m_time = sum;
}

// One sub-step of length h, in stages.
namespace {

// The part of the models that has a potential (gravity, spring, homing,
// mutual gravity, the unclamped point force): what is left of the
// acceleration once it is taken away does work that energy() cannot see.
WorldSettings conservativeOnly(WorldSettings s)
{
    for (const ForceModelInfo& model : forceModels())
        if (model.conservativePart)
            model.conservativePart(s);
    return s;
}

// Power of the non-conservative forces, Σ m (a − a_conservative)·v, and the
// total external force Σ m a (mutual gravity cancels in pairs, so this is the
// rate of change of momentum the forces cause).
struct Rates {
    double power = 0.0;
    Vec2 force = Vec2::Zero();
};

Rates forceRates(const ForceModel& all, const ForceModel& conservative, const BallState& b, double t)
{
    Matrix2X a, c;
    all.acceleration(b.position, b.velocity, t, a);
    conservative.acceleration(b.position, b.velocity, t, c);
    Rates r;
    r.power = ((a - c).cwiseProduct(b.velocity).colwise().sum() * b.mass)(0);
    r.force = a * b.mass;
    return r;
}

} // namespace

void World::startBooks()
{
    const Energy e = energy();
    m_books = Books{};
    m_books.startEnergy = m_books.lastEnergy = e.total();
    m_books.startMomentum = m_books.lastMomentum = momentum();
}

void World::bookEditsSinceLastStep()
{
    // Whatever changed between steps (a setting, a thrown ball, a new ball, the
    // pointer's position in the potential-free sense) was done on purpose.
    const double e = energy().total();
    const Vec2 p = momentum();
    m_books.bookedEnergy += e - m_books.lastEnergy;
    m_books.bookedMomentum += p - m_books.lastMomentum;
}

void World::closeBooks()
{
    m_books.lastEnergy = energy().total();
    m_books.lastMomentum = momentum();
}

void World::setAccounting(bool on)
{
    if (on == m_accounting)
        return;
    m_accounting = on;
    if (on)
        startBooks();
}

double World::energyDrift() const
{
    return energy().total() - m_books.startEnergy - m_books.bookedEnergy;
}

Vec2 World::momentumDrift() const
{
    return momentum() - m_books.startMomentum - m_books.bookedMomentum;
}

// Pinned balls back where the step found them, at rest. Their forces are 0
// and their inverse masses too, so nothing should have moved them; this is
// the guarantee, to the bit, whatever a stage did (a wall that a pinned ball
// overlaps, a push shared with a ball that is stuck at a wall).
void World::holdPinned()
{
    for (std::size_t k = 0; k < m_pinnedIndex.size(); ++k) {
        const int i = m_pinnedIndex[k];
        m_balls.position.col(i) = m_pinnedPosition.col(static_cast<Eigen::Index>(k));
        m_balls.velocity.col(i).setZero();
    }
}

void World::subStep(double h)
{
    const WorldSettings& s = m_settings;
    const ForceModel forces(s, m_balls, m_inputs);
    // Accounting: the forces' work and impulse by the trapezoid rule.
    std::optional<WorldSettings> conservativeSettings;
    Rates before;
    if (m_accounting) {
        conservativeSettings = conservativeOnly(s);
        before = forceRates(ForceModel(s, m_balls, m_inputs), ForceModel(*conservativeSettings, m_balls, m_inputs),
                            m_balls, m_time + m_subTime);
    }
    // Every wall model reads the start of the sub-step (walls.h: a ball resting
    // on a wall is told apart from one that fell onto it), except where the
    // resting solver holds balls on the walls itself (the walls are rows of
    // its solve, and a ball it holds there falls asleep).
    const bool anyWall = s.walls.left || s.walls.right || s.walls.top || s.walls.bottom || s.walls.middle;
    const bool restingSolverHoldsWalls = s.collisions.response == Response::Impulse2D && s.collisions.resting &&
                                         !s.collisions.continuous && s.gravity.enabled && s.gravity.g.norm() > 0.0;
    const bool keepStart = s.walls.model == WallModel::Exact || s.walls.middle ||
                           (anyWall && !restingSolverHoldsWalls) ||
                           (s.collisions.response != Response::None && s.collisions.continuous);
    if (keepStart) {
        m_startPosition = m_balls.position;
        m_startVelocity = m_balls.velocity;
    }

    // 1. Integrate: forces are evaluated at the integrator's stages.
    IntegratorStats integration;
    m_integrator.advance(s.time.integrator, forces, m_balls.position, m_balls.velocity, m_time + m_subTime, h,
                         s.time.tolerance, integration);
    if (integration.gaveUp) { // the step will be undone: stop here
        m_gaveUp = true;
        m_stuckSubStep = integration.tooShort ? integration.shortestSubStep : 0.0;
        m_integrator.invalidate();
        m_last.forceEvaluations += forces.evaluations();
        return;
    }
    m_subTime += h;
    if (m_accounting) {
        const Rates after = forceRates(ForceModel(s, m_balls, m_inputs),
                                       ForceModel(*conservativeSettings, m_balls, m_inputs), m_balls,
                                       m_time + m_subTime);
        m_books.bookedEnergy += 0.5 * (before.power + after.power) * h;
        m_books.bookedMomentum += 0.5 * (before.force + after.force) * h;
    }
    // The stages below change the state on purpose: book what they do.
    const double energyBeforeStages = m_accounting ? energy().total() : 0.0;
    const Vec2 momentumBeforeStages = m_accounting ? momentum() : Vec2::Zero();

    // 2. Speed limit: a crude stand-in for terminal velocity, |v| ≤ max.
    bool touched = false;
    if (s.speedLimit.enabled) {
        const Eigen::ArrayXd speed = m_balls.velocity.colwise().norm().transpose().array();
        const Eigen::ArrayXd factor = (s.speedLimit.max / speed).min(1.0);
        if ((factor < 1.0).any()) {
            m_balls.velocity.array().rowwise() *= factor.transpose();
            touched = true;
        }
    }

    // 3. Walls: bounce whatever crossed an enabled wall.
    // (Continuous detection with exact walls bounces them in stage 4 instead,
    // in time order with the ball impacts.)
    std::int64_t hits = CollisionSystem::wallsInTimeOrder(s.collisions, s.walls)
                            ? 0
                            : applyWalls(s,
                                         {m_balls.radius, m_pinnedIndex.empty() ? nullptr : m_balls.pinned.data(),
                                          m_balls.ownRestitutions()},
                                         {m_startPosition, m_startVelocity}, h, m_balls.position,
                                         m_balls.velocity);

    // Walls and the speed limit change momentum on purpose; collisions must
    // not, so only their energy (restitution below 1) is booked.
    const Vec2 momentumAfterWalls = m_accounting ? momentum() : Vec2::Zero();

    // 4. Collisions: only when the scene asks for them.
    CollisionStats collisions;
    if (s.collisions.response != Response::None)
        collisions = m_collisions.step(m_balls, m_startPosition, s.collisions, s.box, s.walls, h, s.gravity.acting(),
                                       StepMotion{&m_startVelocity, s.time.integrator});
    hits += collisions.wallHits;
    holdPinned();

    // A bounce, a collision or a velocity-dependent force makes the kept
    // acceleration stale for Verlet-type integrators.
    if (touched || hits > 0 || collisions.contacts > 0 || !forces.velocityIndependent())
        m_integrator.invalidate();

    if (m_accounting) {
        m_books.bookedEnergy += energy().total() - energyBeforeStages;
        // A pinned ball takes the impulse of every ball that hits it, as a
        // wall does: with pins the whole collision stage is booked.
        m_books.bookedMomentum += momentumAfterWalls - momentumBeforeStages +
                                  (m_pinnedIndex.empty() ? collisions.wallImpulse : momentum() - momentumAfterWalls);
    }

    m_last.forceEvaluations += forces.evaluations();
    m_last.acceptedSteps += integration.accepted;
    m_last.rejectedSteps += integration.rejected;
    m_last.roundingChecks += integration.roundingChecks;
    m_last.toleranceFloor = std::max(m_last.toleranceFloor, integration.toleranceFloor);
    m_last.wallHits += hits;
    m_last.pairsTested += collisions.pairsTested;
    m_last.contacts += collisions.contacts;
}

Energy World::energy() const
{
    Energy e;
    e.kinetic = 0.5 * m_balls.mass.dot(m_balls.velocity.colwise().squaredNorm().transpose());
    e.potential = ForceModel(m_settings, m_balls, m_inputs).potential(m_balls.position);
    return e;
}

Vec2 World::momentum() const
{
    return m_balls.velocity * m_balls.mass;
}

double World::angularMomentum() const
{
    // L = Σ m (x v_y − y v_x), the z component of x × m v.
    const auto& x = m_balls.position;
    const auto& v = m_balls.velocity;
    return m_balls.mass.dot((x.row(0).cwiseProduct(v.row(1)) - x.row(1).cwiseProduct(v.row(0))).transpose());
}

Matrix2X World::accelerations() const
{
    Matrix2X a;
    ForceModel(m_settings, m_balls, m_inputs).acceleration(m_balls.position, m_balls.velocity, m_time, a);
    return a;
}

std::vector<World::SourceAcceleration> World::accelerationBySource(int i) const
{
    std::vector<SourceAcceleration> out;
    if (i < 0 || i >= m_balls.size())
        return out;
    // Each model on its own, as the step's force model would add it: the
    // scale factors come from a ForceModel of the world's own settings.
    const ForceModel all(m_settings, m_balls, m_inputs);
    Matrix2X a;
    for (const ForceModelInfo& model : forceModels()) {
        if (!model.on(m_settings))
            continue;
        a.setZero(2, m_balls.size());
        all.addOne(model, m_balls.position, m_balls.velocity, m_time, a);
        out.push_back(SourceAcceleration{model.name, Vec2(a.col(i))});
    }
    return out;
}

} // namespace forcelab::sim
