// The collision step: detection, then the path the settings choose (collision_system.h).

#include "collision_system.h"

#include "sim/collision/broad_phase/brute_force.h"
#include "sim/integrators/integrator_info.h"
#include "sim/collision/broad_phase/halved.h"
#include "narrow_phase.h"
#include "sim/collision/response/positional_correction.h"
#include "sim/collision/response/response.h"
#include <algorithm>
#include <cmath>
#include <iterator>

namespace forcelab::sim {
namespace {

// The pass over all contacts for one response model (a template, so the
// model's few lines are inlined into the loop; respond() is the same choice
// at run time, for the impacts in time order): per contact, in (a, b) order,
// the line of impact from the detection-time positions, the response, then
// positional correction on the current positions. e is the world's; a ball
// with its own restitution brings the pair's to the smaller of the two.
template <Response Model>
void resolveContacts(const std::vector<Contact>& contacts, const Matrix2X& detected, BallState& balls, double e,
                     const BoxSettings& box, const WallSettings& walls)
{
    double* x = balls.position.data();
    double* v = balls.velocity.data();
    const double* p = detected.data();
    const double* radius = balls.radius.data();
    const double* inverseMass = balls.inverseMass.data();
    const double* own = balls.ownRestitutions(); // nullptr in most scenes
    const WallCheck check{{{walls.left, walls.right}, {walls.top, walls.bottom}}, {box.width, box.height}};
    for (const Contact& c : contacts) {
        const std::size_t a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
        const double ra = radius[a], rb = radius[b], s = ra + rb;
        const double wa = inverseMass[a], wb = inverseMass[b];
        const Vec2 d(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]);
        const Vec2 n = lineOfImpact(d, s, c.a, c.b);
        Vec2 va(v[2 * a], v[2 * a + 1]), vb(v[2 * b], v[2 * b + 1]);
        const double ec = own ? pairRestitution(own[a], own[b], e) : e;
        if (respondAs<Model>(ec, d, n, wa, wb, va, vb)) {
            v[2 * a] = va.x();
            v[2 * a + 1] = va.y();
            v[2 * b] = vb.x();
            v[2 * b + 1] = vb.y();
        }
        Vec2 pa(x[2 * a], x[2 * a + 1]), pb(x[2 * b], x[2 * b + 1]);
        const double depth = s - (pb - pa).norm();
        if (!(depth > 0.0))
            continue;
        pushApartWithin(pa, pb, {ra, rb, n, wa, wb}, depth, check, box, walls);
        x[2 * a] = pa.x();
        x[2 * a + 1] = pa.y();
        x[2 * b] = pb.x();
        x[2 * b + 1] = pb.y();
    }
}

} // namespace

void CollisionSystem::allowSleep(bool on)
{
    if (!on)
        m_sleep.wakeAll();
    m_sleepAllowed = on;
}

bool CollisionSystem::everyBallSleeps(const CollisionSettings& settings, int n, const Vec2& gravity,
                                      double dt) const
{
    if (n == 0 || !m_sleptThrough || m_sleep.count() != n)
        return false;
    const StepPlan plan = planStep(settings, settings.continuous, gravity, dt);
    return plan.path == StepPath::Speculative && plan.sleeping;
}

// What every step starts from: the last step's counters cleared.
void CollisionSystem::beginStep()
{
    m_lastLimitReached = false;
    m_lastPasses = 0;
    m_lastBounceRows = 0;
    m_lastBounced = false;
    if (m_profiling)
        ++m_profile.calls;
}

CollisionStats CollisionSystem::stayAsleep()
{
    beginStep();
    CollisionStats stats;
    stats.contacts = static_cast<std::int64_t>(m_contacts.size());
    return stats;
}

// How far x − v·h misses the start of a sub-step under gravity, in g·h², as
// the solver takes it back (sub_step_context.h).
static double startLag(IntegratorKind integrator)
{
    return integratorInfo(integrator).path == StepPath::DriftKick ? 1.0 : 0.0;
}

SubStepContext CollisionSystem::subStep(const CollisionSettings& settings, const BoxSettings& box,
                                        const WallSettings& walls, double h, double restingSpeed,
                                        const Vec2& gravity, const StepMotion& motion, const BallState& balls) const
{
    SubStepContext c;
    c.h = h;
    c.inverseH = 1.0 / h;
    c.box = box;
    c.walls = walls;
    c.restitution = settings.restitution;
    c.ownRestitution = balls.ownRestitutions();
    c.restingSpeed = restingSpeed;
    c.gravity = gravity.norm();
    c.gravityX = gravity.x();
    c.gravityY = gravity.y();
    c.solver = m_solver;
    c.startLag = startLag(motion.integrator);
    c.sameForce = m_sameForce;
    return c;
}

void CollisionSystem::findContacts(Detection method, bool swept, std::vector<Contact>& out, CollisionStats& stats,
                                   StageClock& clock)
{
    out.clear();
    const int n = m_input.size();
    auto run = [&](const auto& test) {
        switch (method) {
        case Detection::Brute:
            bruteForcePairs(n, test, out, stats);
            clock.lap(m_profile.pairs);
            return; // already in (a, b) order
        case Detection::Halved:
            halvedPairs(n, test, out, stats);
            clock.lap(m_profile.pairs);
            return; // already in (a, b) order
        case Detection::Sweep:
            m_sweep.findPairs(m_input, test, out, stats, clock, m_profile);
            break;
        case Detection::Grid:
            m_grid.findPairs(m_input, test, out, stats, clock, m_profile);
            break;
        }
        m_sorter.sort(out, n);
        clock.lap(m_profile.contactSort);
    };
    if (swept) {
        run(SweptTest{BallArrays{m_input.x.data(), m_input.y.data(), m_input.r.data(), m_input.x0.data(),
                                 m_input.y0.data()}});
    } else {
        run(OverlapTest{BallArrays{m_input.x.data(), m_input.y.data(), m_input.r.data()}});
    }
    stats.contacts += static_cast<std::int64_t>(out.size());
}

CollisionStats CollisionSystem::detect(const BallState& balls, Detection method, std::vector<Contact>& out)
{
    CollisionStats stats;
    StageClock clock(m_profiling);
    m_input.loadStatic(balls);
    clock.lap(m_profile.load);
    findContacts(method, false, out, stats, clock);
    return stats;
}

CollisionStats CollisionSystem::detectMoving(const BallState& balls, const Matrix2X& startPositions,
                                             Detection method, std::vector<Contact>& out)
{
    CollisionStats stats;
    StageClock clock(m_profiling);
    if (startPositions.cols() != balls.size())
        m_input.loadStatic(balls);
    else
        m_input.loadSwept(balls, startPositions);
    clock.lap(m_profile.load);
    findContacts(method, startPositions.cols() == balls.size(), out, stats, clock);
    return stats;
}

// The step picks one of its paths once (StepPath), then runs it.
CollisionSystem::StepPlan CollisionSystem::planStep(const CollisionSettings& settings, bool continuous,
                                                    const Vec2& gravity, double dt) const
{
    StepPlan plan;
    if (settings.response == Response::None)
        return plan; // StepPath::Nothing
    if (continuous && settings.response != Response::Flag) {
        plan.path = StepPath::InTimeOrder;
        return plan;
    }
    plan.restingSpeed = m_solver.restingFactor * gravity.norm() * dt;
    const bool resting = settings.resting && settings.response == Response::Impulse2D && !continuous &&
                         plan.restingSpeed > 0.0 && std::isfinite(plan.restingSpeed);
    // Sleeping needs the staged solve with speculative contacts; any other
    // step wakes every ball.
    plan.sleeping = resting && m_solver.speculative > 0.0 && m_solver.stages > 1 && m_sleepAllowed &&
                    m_solver.sleepTime > 0.0;
    plan.swept = continuous;
    if (resting && m_solver.speculative > 0.0)
        plan.path = StepPath::Speculative;
    else if (settings.response == Response::Flag)
        plan.path = StepPath::Flag;
    else if (resting)
        plan.path = StepPath::Resting;
    else
        plan.path = StepPath::OnePass;
    return plan;
}

CollisionStats CollisionSystem::step(BallState& balls, const Matrix2X& startPositions,
                                     const CollisionSettings& settings, const BoxSettings& box,
                                     const WallSettings& walls, double dt, const Vec2& gravity,
                                     const StepMotion& motion)
{
    CollisionStats stats;
    beginStep();
    StageClock clock(m_profiling);
    const int n = balls.size();
    balls.colliding.assign(static_cast<std::size_t>(n), 0);
    const StepPlan plan = planStep(settings, settings.continuous && startPositions.cols() == n, gravity, dt);
    m_sleptThrough = false; // until the sleeping path finds it so
    // Only the speculative path lets balls sleep; every other step (but one
    // that does nothing) wakes them all.
    if (plan.path == StepPath::InTimeOrder || (plan.path != StepPath::Nothing && !plan.sleeping))
        m_sleep.wakeAll();
    switch (plan.path) {
    case StepPath::Nothing:
        m_contacts.clear();
        break;
    case StepPath::InTimeOrder:
        stats = stepInTimeOrder(balls, startPositions, settings, box, walls, dt, motion, clock);
        break;
    case StepPath::Speculative:
        stepSpeculative(balls, settings, box, walls, dt, gravity, motion, plan, stats, clock);
        break;
    case StepPath::Flag:
        stepFlag(balls, startPositions, settings, plan, stats, clock);
        break;
    case StepPath::Resting:
        stepResting(balls, settings, box, walls, dt, gravity, motion, plan, stats, clock);
        break;
    case StepPath::OnePass:
        stepOnePass(balls, settings, box, walls, stats, clock);
        break;
    }
    return stats;
}

// Resting contact with speculative contacts (and sleep, when allowed): the
// solver finds the touching pairs among the grown ones as it builds its rows.
void CollisionSystem::stepSpeculative(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                                      const WallSettings& walls, double dt, const Vec2& gravity,
                                      const StepMotion& motion, const StepPlan& plan, CollisionStats& stats,
                                      StageClock& clock)
{
    const double g = gravity.norm();
    const bool sleeping = plan.sleeping;
    const bool allAsleep = sleeping && m_sleep.count() == balls.size() && balls.size() > 0;
    if (sleeping) {
        m_sleep.hold(balls); // the sleepers back where they sleep, before anything reads them
        clock.lap(m_profile.sleep);
    }
    // Speculative contacts: every ball grown by the distance one sub-step
    // can bring it closer to a neighbour, |v − u|·h + |g|·h² with u the
    // mean velocity around it, at most `speculative` of its radius
    // (speculative_margin.h). The grown pairs include every overlapping
    // pair (a sum of larger numbers is never smaller in floating point),
    // and all four detectors find the same grown pairs in the same order.
    m_margin.compute(balls, dt, g * dt * dt, m_solver.speculative, m_grow);
    m_input.loadStatic(balls, m_grow.data());
    clock.lap(m_profile.load);
    findContacts(settings.detection, false, m_speculative, stats, clock);
    const double stillSpeed = m_solver.stillShare * plan.restingSpeed;
    if (sleeping) {
        m_sleep.wakeNear(balls, m_speculative, gravity * dt, dt, startLag(motion.integrator), stillSpeed,
                         m_solver.wakeShare * plan.restingSpeed, m_solver.wakeLayers);
        clock.lap(m_profile.sleep);
    }
    // The solver puts the pairs that overlap now back into m_contacts
    // (what contacts(), the flags and the counters report) as it builds
    // its rows.
    m_resting.solve(balls, subStep(settings, box, walls, dt, plan.restingSpeed, gravity, motion, balls), m_speculative,
                    &m_contacts, clock, m_profile, sleeping ? m_sleep.asleep() : nullptr);
    if (sleeping) {
        m_sleep.settle(balls, m_speculative, m_resting.held(), dt, stillSpeed, m_solver.sleepTime);
        clock.lap(m_profile.sleep);
        m_sleptThrough = allAsleep && m_sleep.count() == balls.size();
    }
    noteRestingSolve();
    stats.contacts = static_cast<std::int64_t>(m_contacts.size());
}

// The touching pairs at the end of the (sub-)step into m_contacts, flagged
// in balls.colliding; with `startPositions`, also the pairs whose straight
// paths from there met during it.
void CollisionSystem::detectTouching(BallState& balls, const Matrix2X* startPositions,
                                     const CollisionSettings& settings, CollisionStats& stats, StageClock& clock)
{
    if (startPositions)
        m_input.loadSwept(balls, *startPositions);
    else
        m_input.loadStatic(balls);
    clock.lap(m_profile.load);
    findContacts(settings.detection, startPositions != nullptr, m_contacts, stats, clock);
    for (const Contact& c : m_contacts) {
        balls.colliding[static_cast<std::size_t>(c.a)] = 1;
        balls.colliding[static_cast<std::size_t>(c.b)] = 1;
    }
    clock.lap(m_profile.build);
}

// The resting solver's counters of the solve that just ran.
void CollisionSystem::noteRestingSolve()
{
    m_lastPasses = m_resting.lastPasses();
    m_lastBounceRows = m_resting.lastBounceRows();
    m_lastBounced = m_resting.lastBounced();
    if (m_profiling)
        m_profile.passes += m_lastPasses;
}

// The touching pairs marked, nothing else.
void CollisionSystem::stepFlag(BallState& balls, const Matrix2X& startPositions, const CollisionSettings& settings,
                               const StepPlan& plan, CollisionStats& stats, StageClock& clock)
{
    detectTouching(balls, plan.swept ? &startPositions : nullptr, settings, stats, clock);
    m_resting.forget(); // no resting solve: nothing to warm-start from next time
}

// Resting contact on the touching pairs alone (no speculative contacts).
void CollisionSystem::stepResting(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                                  const WallSettings& walls, double dt, const Vec2& gravity, const StepMotion& motion,
                                  const StepPlan& plan, CollisionStats& stats, StageClock& clock)
{
    detectTouching(balls, nullptr, settings, stats, clock);
    m_resting.solve(balls, subStep(settings, box, walls, dt, plan.restingSpeed, gravity, motion, balls), m_contacts,
                    nullptr, clock, m_profile);
    noteRestingSolve();
}

// One pass of the response over the touching pairs, then positional
// correction (resolve()).
void CollisionSystem::stepOnePass(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                                  const WallSettings& walls, CollisionStats& stats, StageClock& clock)
{
    detectTouching(balls, nullptr, settings, stats, clock);
    m_resting.forget(); // no resting solve: nothing to warm-start from next time
    if (!m_contacts.empty())
        resolve(balls, settings, box, walls);
    clock.lap(m_profile.correction);
}

void CollisionSystem::resolve(BallState& balls, const CollisionSettings& settings, const BoxSettings& box,
                              const WallSettings& walls)
{
    // Normals come from the positions at detection, not from positions already
    // moved by earlier pairs of this pass: the line of impact of a pair does not
    // depend on the order, and balls stacked on one point get the spread-out
    // fallback directions of lineOfImpact for every pair.
    m_detected = balls.position;
    const double e = settings.restitution;
    switch (settings.response) {
    case Response::None:
    case Response::Flag:
        return;
    case Response::Reverse1D:
        return resolveContacts<Response::Reverse1D>(m_contacts, m_detected, balls, e, box, walls);
    case Response::Elastic1D:
        return resolveContacts<Response::Elastic1D>(m_contacts, m_detected, balls, e, box, walls);
    case Response::Axis2D:
        return resolveContacts<Response::Axis2D>(m_contacts, m_detected, balls, e, box, walls);
    case Response::Impulse2D:
        return resolveContacts<Response::Impulse2D>(m_contacts, m_detected, balls, e, box, walls);
    }
}

bool CollisionSystem::wallsInTimeOrder(const CollisionSettings& settings, const WallSettings& walls)
{
    return settings.continuous && settings.response != Response::None && settings.response != Response::Flag &&
           walls.model == WallModel::Exact;
}

CollisionStats CollisionSystem::stepInTimeOrder(BallState& balls, const Matrix2X& startPositions,
                                                const CollisionSettings& settings, const BoxSettings& box,
                                                const WallSettings& walls, double dt, const StepMotion& motion,
                                                StageClock& clock)
{
    CollisionStats stats;
    const Vec2 momentumBefore = balls.velocity * balls.mass;
    // Every pair whose paths may meet: the swept test on the straight lines
    // between each ball's ends, each ball grown by how far its path bends
    // away from that line.
    // Without the walls in the loop the world's wall stage has already changed
    // the end velocity of a ball that hit one, so the path cannot be read from
    // it: straight paths from start to end then.
    const bool wallsHere = wallsInTimeOrder(settings, walls);
    const std::vector<double>& bend =
        m_events.preparePaths(balls, startPositions, wallsHere ? motion : StepMotion{}, dt);
    m_input.loadSwept(balls, startPositions, bend.data());
    clock.lap(m_profile.load);
    findContacts(settings.detection, true, m_candidates, stats, clock);
    const ImpactCounts counts = m_events.run(balls, m_candidates, settings, box, walls, wallsHere, m_met);
    m_lastLimitReached = counts.limitReached;
    clock.lap(m_profile.velocity);
    // What still overlaps at the end began the step overlapping (spawned so,
    // or pushed by a wall) or is left from the impact limit: the discrete
    // pass, with positional correction.
    m_input.loadStatic(balls);
    clock.lap(m_profile.load);
    findContacts(settings.detection, false, m_contacts, stats, clock);
    if (!m_contacts.empty())
        resolve(balls, settings, box, walls);
    clock.lap(m_profile.correction);
    // Reported contacts: the pairs that met during the step and those that overlap at its end.
    if (!m_met.empty()) {
        m_candidates.clear();
        std::set_union(m_met.begin(), m_met.end(), m_contacts.begin(), m_contacts.end(),
                       std::back_inserter(m_candidates),
                       [](const Contact& l, const Contact& r) { return l.a < r.a || (l.a == r.a && l.b < r.b); });
        m_contacts.swap(m_candidates);
    }
    for (const Contact& c : m_contacts) {
        balls.colliding[static_cast<std::size_t>(c.a)] = 1;
        balls.colliding[static_cast<std::size_t>(c.b)] = 1;
    }
    m_resting.forget(); // no resting solve: nothing to warm-start from next time
    stats.contacts = static_cast<std::int64_t>(m_contacts.size());
    stats.pairsTested += counts.pairsTested;
    stats.impacts = counts.ballImpacts;
    stats.limitReached = counts.limitReached ? 1 : 0;
    if (wallsHere) {
        stats.wallHits = counts.wallHits;
        stats.wallImpulse = balls.velocity * balls.mass - momentumBefore;
    }
    return stats;
}

} // namespace forcelab::sim
