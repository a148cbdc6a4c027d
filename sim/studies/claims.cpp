#include "sim/studies/claims.h"
#include "sim/world/scene_keys.h"

#include "sim/world/error.h"
#include "sim/world/parameters.h"
#include "sim/world/world.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>

namespace forcelab::sim {

namespace {

using W = MeasureWhen;

constexpr std::array kMeasures{
    ClaimMeasure{"position", "px", W::At, true, "the ball's x or y (axis) at the moment `at`; y points down"},
    ClaimMeasure{"velocity", "px/s", W::At, true, "the ball's vx or vy (axis) at the moment `at`"},
    ClaimMeasure{"speed", "px/s", W::At, true, "the ball's speed |v| at the moment `at`"},
    ClaimMeasure{"height", "px", W::At, true,
                 "how high the bottom of the ball is above the floor at the moment `at`: box height − y − r"},
    ClaimMeasure{"distance", "px", W::At, true, "the distance between the centres of `ball` and `other` at `at`"},
    ClaimMeasure{"mean_speed", "px/s", W::At, false, "the mean speed of all balls at the moment `at`"},
    ClaimMeasure{"max_speed", "px/s", W::At, false, "the largest speed of any ball at the moment `at`"},
    ClaimMeasure{"near_wall", "balls", W::At, false,
                 "how many balls have their edge within `distance` px of a side of the box at `at`"},
    ClaimMeasure{"top_height", "px", W::At, false,
                 "the height of the highest ball top above the floor at `at`: box height − min(y − r)"},
    ClaimMeasure{"energy_drift", "1", W::OverRun, false,
                 "the largest |E − E₀| / |E₀| from 0 to `at`, E the total energy (kinetic plus potential)"},
    ClaimMeasure{"momentum_drift", "1", W::OverRun, false,
                 "the largest |p − p₀| from 0 to `at`, as a fraction of Σ m|v| at the start (not measurable when nothing "
                 "moves at the start: use `momentum`)"},
    ClaimMeasure{"min_gap", "px", W::OverRun, false,
                 "the smallest gap between the surfaces of two balls from 0 to `at` (below 0: they overlapped)"},
    ClaimMeasure{"max_height", "px", W::OverRun, true, "the greatest height of the ball above the floor from 0 to `at`"},
    ClaimMeasure{"min_height", "px", W::OverRun, true, "the smallest height of the ball above the floor from 0 to `at`"},
    ClaimMeasure{"max_position", "px", W::OverRun, true, "the largest x or y (axis) of the ball from 0 to `at`"},
    ClaimMeasure{"min_position", "px", W::OverRun, true, "the smallest x or y (axis) of the ball from 0 to `at`"},
    ClaimMeasure{"wall_hits", "hits", W::OverRun, false, "how many times balls hit a wall from 0 to `at`"},
    ClaimMeasure{"apex", "px", W::Event, true,
                 "the ball's height above the floor at its n-th highest point (where it stops rising), "
                 "not counting where it starts"},
    ClaimMeasure{"turn_time", "s", W::Event, true,
                 "the time of the ball's n-th turning point along `axis` (its velocity along the axis changes sign)"},
    ClaimMeasure{"period", "s", W::Event, true,
                 "the mean time of one full swing along `axis` over the first n swings, from one turning point "
                 "to the next of the same kind"},
    ClaimMeasure{"stopped", "1", W::At, false,
                 "1 when the simulation stopped itself before `at` because the motion blows up (its message says "
                 "why), else 0"},
    ClaimMeasure{"acceleration_ratio", "1", W::At, true,
                 "the ball's acceleration along `axis` divided by that of ball `other` at the moment `at`, as the "
                 "acceleration arrows show them"},
    ClaimMeasure{"momentum", "mass·px/s", W::At, false,
                 "the size of the total momentum |Σ m v| at the moment `at` (0 for a system that starts at rest "
                 "and is pushed only by its own pairs of forces)"},
    ClaimMeasure{"overlapping", "balls", W::At, false,
                 "how many balls overlap at least one other ball at the moment `at` (their centres are closer than "
                 "the sum of their radii)"},
    ClaimMeasure{"ball_count", "balls", W::At, false, "how many balls the world holds at the moment `at`"},
    ClaimMeasure{"energy_ratio", "1", W::At, false,
                 "the total energy (kinetic plus potential) at the moment `at` divided by that at the start"},
    ClaimMeasure{"contacts", "contacts", W::OverRun, false,
                 "how many ball–ball contacts the collision detection found from 0 to `at` (a contact that lasts "
                 "several steps counts once a step)"},
    ClaimMeasure{"tests_per_step", "tests", W::At, false,
                 "how many pairs the collision detection tested with the exact distance test in the step that ends "
                 "at `at` (0 when collisions are off)"},
};

std::string number(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

/// The parts joined (std::string's operator+ chains trip GCC 12's -Wrestrict).
std::string cat(std::initializer_list<std::string_view> parts)
{
    std::string out;
    for (std::string_view p : parts)
        out.append(p);
    return out;
}

double component(const Vec2& v, char axis)
{
    return axis == 'x' ? v.x() : v.y();
}

/// Where a velocity component changed sign inside a step: the time into the
/// step and the coordinate there, taking the acceleration as constant over
/// the step (exact for gravity): a = (v₁ − v₀)/h, so v = 0 at τ = −v₀/a and
/// the coordinate there is x₀ − v₀²/(2a).
struct Turn {
    double time;
    double coordinate;
    bool minimum; ///< the coordinate is at a low point (velocity from − to +)
};

std::optional<Turn> turnInStep(double t0, double h, double x0, double v0, double v1)
{
    if (!(v0 < 0.0 && v1 >= 0.0) && !(v0 > 0.0 && v1 <= 0.0))
        return std::nullopt;
    const double a = (v1 - v0) / h;
    const double tau = a != 0.0 ? std::clamp(-v0 / a, 0.0, h) : 0.0;
    return Turn{t0 + tau, x0 + v0 * tau + 0.5 * a * tau * tau, v0 < 0.0};
}

/// The running values of one claim while the world steps.
class Measurer {
public:
    Measurer(const Claim& claim, const ClaimMeasure& row) : m_claim(claim), m_row(row) {}

    void start(const World& w)
    {
        m_e0 = w.energy().total();
        m_p0 = w.momentum();
        const BallState& b = w.balls();
        m_pScale = (b.velocity.colwise().norm().transpose().array() * b.mass.array()).sum();
        overRun(w);
    }

    /// After each step: `x0`, `v0` are the measured ball's position and
    /// velocity before it, `t0` its start time. Returns true when done.
    bool afterStep(const World& w, double t0, const Vec2& x0, const Vec2& v0)
    {
        overRun(w);
        if (m_row.when != W::Event)
            return false;
        const double h = w.time() - t0;
        const char axis = m_row.name == "apex" ? 'y' : m_claim.axis;
        const Vec2 v1 = w.balls().velocity.col(m_claim.ball);
        const auto turn = turnInStep(t0, h, component(x0, axis), component(v0, axis), component(v1, axis));
        if (!turn)
            return false;
        if (m_row.name == "apex") {
            if (!turn->minimum) // y down: the highest point is where y stops falling
                return false;
            if (++m_events == m_claim.occurrence) {
                m_value = floorHeight(w, turn->coordinate);
                return true;
            }
        } else if (m_row.name == "turn_time") {
            if (++m_events == m_claim.occurrence) {
                m_value = turn->time;
                return true;
            }
        } else { // period: turning points of the first kind seen, n + 1 of them
            if (m_events == 0)
                m_kind = turn->minimum;
            if (turn->minimum != m_kind)
                return false;
            if (m_events == 0)
                m_firstTurn = turn->time;
            if (++m_events == m_claim.occurrence + 1) {
                m_value = (turn->time - m_firstTurn) / m_claim.occurrence;
                return true;
            }
        }
        return false;
    }

    /// The measured value once the run is over (NaN for an event that did not come).
    double finish(const World& w) const
    {
        if (m_row.when == W::OverRun || m_row.when == W::Event)
            return m_value;
        const BallState& b = w.balls();
        const std::string_view name = m_row.name;
        const int i = m_claim.ball;
        if (name == "position")
            return component(b.position.col(i), m_claim.axis);
        if (name == "velocity")
            return component(b.velocity.col(i), m_claim.axis);
        if (name == "speed")
            return b.velocity.col(i).norm();
        if (name == "height")
            return floorHeight(w, b.position(1, i));
        if (name == "distance")
            return (b.position.col(i) - b.position.col(m_claim.other)).norm();
        if (name == "acceleration_ratio") {
            const Matrix2X a = w.accelerations();
            const double other = component(a.col(m_claim.other), m_claim.axis);
            return other != 0.0 ? component(a.col(i), m_claim.axis) / other : std::numeric_limits<double>::quiet_NaN();
        }
        if (name == "tests_per_step")
            return static_cast<double>(w.lastStep().pairsTested);
        if (name == "stopped")
            return w.halted() ? 1.0 : 0.0;
        if (name == "momentum")
            return w.momentum().norm();
        if (name == "ball_count")
            return b.size();
        if (name == "energy_ratio")
            return m_e0 != 0.0 ? w.energy().total() / m_e0 : std::numeric_limits<double>::quiet_NaN();
        if (name == "overlapping") {
            // The collision detection's own touching pairs (sort and sweep),
            // not a test of every pair: a lesson may hold 200,000 balls.
            CollisionSystem detector;
            std::vector<Contact> pairs;
            detector.detect(b, Detection::Sweep, pairs);
            std::vector<char> hit(std::size_t(b.size()), 0);
            for (const Contact& c : pairs)
                hit[std::size_t(c.a)] = hit[std::size_t(c.b)] = 1;
            return double(std::count(hit.begin(), hit.end(), 1));
        }
        if (b.size() == 0)
            return std::numeric_limits<double>::quiet_NaN();
        const Eigen::VectorXd speed = b.velocity.colwise().norm().transpose();
        if (name == "mean_speed")
            return speed.mean();
        if (name == "max_speed")
            return speed.maxCoeff();
        const BoxSettings& box = w.settings().box;
        if (name == "near_wall") {
            int count = 0;
            for (int k = 0; k < b.size(); ++k) {
                const double x = b.position(0, k), y = b.position(1, k), r = b.radius[k];
                const double gap = std::min({x - r, box.width - x - r, y - r, box.height - y - r});
                count += gap <= m_claim.distance ? 1 : 0;
            }
            return count;
        }
        // top_height
        return box.height - (b.position.row(1).transpose() - b.radius).minCoeff();
    }

private:
    /// Height above the floor of the bottom of the measured ball with its centre at y.
    double floorHeight(const World& w, double y) const
    {
        return w.settings().box.height - y - w.balls().radius[m_claim.ball];
    }

    void overRun(const World& w)
    {
        if (m_row.when != W::OverRun)
            return;
        const BallState& b = w.balls();
        const std::string_view name = m_row.name;
        double v = 0.0;
        bool largest = true;
        if (name == "energy_drift") {
            v = std::abs(w.energy().total() - m_e0) / std::max(std::abs(m_e0), 1e-300);
        } else if (name == "momentum_drift") {
            if (!(m_pScale > 0.0)) // nothing moves at the start: no scale to measure against
                return;
            v = (w.momentum() - m_p0).norm() / m_pScale;
        } else if (name == "min_gap") {
            largest = false;
            v = std::numeric_limits<double>::infinity();
            for (int i = 0; i < b.size(); ++i)
                for (int j = i + 1; j < b.size(); ++j)
                    v = std::min(v, (b.position.col(i) - b.position.col(j)).norm() - b.radius[i] - b.radius[j]);
        } else if (name == "max_height" || name == "min_height") {
            largest = name == "max_height";
            v = floorHeight(w, b.position(1, m_claim.ball));
        } else if (name == "max_position" || name == "min_position") {
            largest = name == "max_position";
            v = component(b.position.col(m_claim.ball), m_claim.axis);
        } else if (name == "contacts") {
            m_value = static_cast<double>(w.totals().contacts);
            return;
        } else { // wall_hits
            m_value = static_cast<double>(w.totals().wallHits);
            return;
        }
        if (std::isnan(m_value))
            m_value = v;
        else
            m_value = largest ? std::max(m_value, v) : std::min(m_value, v);
    }

    const Claim& m_claim;
    const ClaimMeasure& m_row;
    double m_value = std::numeric_limits<double>::quiet_NaN();
    double m_e0 = 0.0;
    Vec2 m_p0 = Vec2::Zero();
    double m_pScale = 0.0;
    int m_events = 0;
    bool m_kind = false;      // period: the kind of turning point counted
    double m_firstTurn = 0.0; // period: time of the first one
};

ClaimResult refused(std::string why)
{
    ClaimResult r;
    r.measured = std::numeric_limits<double>::quiet_NaN();
    r.explanation = std::move(why);
    return r;
}

} // namespace

std::span<const ClaimMeasure> claimMeasures()
{
    return kMeasures;
}

const ClaimMeasure* findClaimMeasure(std::string_view name)
{
    for (const ClaimMeasure& m : kMeasures)
        if (m.name == name)
            return &m;
    return nullptr;
}

ClaimResult checkClaim(const Scene& scene, const Claim& claim, const ClaimProgress& progress)
{
    const ClaimMeasure* row = findClaimMeasure(claim.measure);
    if (!row)
        return refused(cat({"no measurement called \"", claim.measure, "\""}));
    if (!(claim.at >= 0.0) || !std::isfinite(claim.at))
        return refused("the time `at` must be a number of seconds ≥ 0");
    Scene changed = scene;
    for (const auto& [key, value] : claim.set) {
        if (isSceneKey(key)) {
            if (const auto problem = setSceneKey(changed, key, value))
                return refused(cat({"cannot set ", key, ": ", *problem}));
            continue;
        }
        const Parameter* p = findParameter(key);
        if (!p)
            return refused(cat({"no parameter called \"", key, "\" to set"}));
        p->set(changed.settings, value);
    }
    if (const auto problem = checkSpawnRanges(changed.spawn))
        return refused(cat({"cannot set the random balls so: ", *problem}));
    std::optional<World> world;
    try {
        world.emplace(changed);
    } catch (const InvalidInput& e) {
        return refused(cat({"the scene is invalid: ", e.what()}));
    }
    World& w = *world;
    const int n = w.balls().size();
    const bool usesOther = row->name == "distance" || row->name == "acceleration_ratio";
    if (row->perBall && (claim.ball < 0 || claim.ball >= n || (usesOther && (claim.other < 0 || claim.other >= n))))
        return refused(cat({"the scene has ", std::to_string(n), n == 1 ? " ball" : " balls", ", so there is no ball ",
                            std::to_string(usesOther && claim.ball >= 0 && claim.ball < n ? claim.other : claim.ball)}));

    Measurer m(claim, *row);
    m.start(w);
    // Steps until `at`; a step that would end past it by less than half a
    // step still runs, so `at` is met to within half a step.
    const double dt = w.settings().time.dt;
    bool done = false;
    while (!done && w.time() < claim.at - 0.5 * dt && !w.halted()) {
        const double t0 = w.time();
        const Vec2 x0 = row->perBall ? Vec2(w.balls().position.col(claim.ball)) : Vec2::Zero();
        const Vec2 v0 = row->perBall ? Vec2(w.balls().velocity.col(claim.ball)) : Vec2::Zero();
        w.step();
        done = m.afterStep(w, t0, x0, v0);
        if (progress && !progress(claim.at > 0.0 ? std::min(1.0, w.time() / claim.at) : 1.0)) {
            ClaimResult stopped = refused("cancelled before the run reached the claim's time");
            stopped.cancelled = true;
            return stopped;
        }
    }
    ClaimResult r;
    r.measured = m.finish(w);
    if (w.halted() && row->name != "stopped")
        return refused(cat({"the simulation stopped itself at t = ", number(w.time()), " s: ", *w.halted()}));
    if (std::isnan(r.measured))
        return refused(row->when == W::Event ? cat({"event ", std::to_string(claim.occurrence), " (", row->name,
                                                    ") did not happen before t = ", number(claim.at), " s"})
                                             : std::string("nothing to measure"));
    const std::string unit = row->unit == "1" ? std::string() : cat({" ", row->unit});
    std::string stated;
    switch (claim.test) {
    case ClaimTest::Near: {
        const double allowed = claim.relative ? claim.tolerance * std::abs(claim.value) : claim.tolerance;
        r.holds = std::abs(r.measured - claim.value) <= allowed;
        stated = cat({number(claim.value), unit, " ± ", number(claim.relative ? 100.0 * claim.tolerance : claim.tolerance),
                      claim.relative ? std::string_view("%") : std::string_view(unit)});
        break;
    }
    case ClaimTest::Below:
        r.holds = r.measured < claim.value;
        stated = cat({"below ", number(claim.value), unit});
        break;
    case ClaimTest::Above:
        r.holds = r.measured > claim.value;
        stated = cat({"above ", number(claim.value), unit});
        break;
    }
    r.explanation = cat({"measured ", number(r.measured), unit, ", stated ", stated});
    return r;
}

std::string describe(const Claim& claim, const ClaimResult& result)
{
    std::string line = result.holds ? "holds: " : "FAILS: ";
    line.append(claim.text).append(" (").append(claim.measure).append(": ").append(result.explanation).append(")");
    return line;
}

} // namespace forcelab::sim
