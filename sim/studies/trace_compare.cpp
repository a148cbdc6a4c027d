#include "sim/studies/trace_compare.h"

#include "sim/world/names.h"
#include "sim/world/world.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace forcelab::sim {

TraceMatch matchTrace(const Scene& scene, const std::vector<StudentRow>& rows, double tolerance)
{
    TraceMatch m;
    // First step, then first ball: the order "where it first departs" means.
    std::vector<std::size_t> order(rows.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return rows[a].step != rows[b].step ? rows[a].step < rows[b].step : rows[a].ball < rows[b].ball;
    });
    if (!rows.empty())
        m.lastStep = rows[order.back()].step;
    World world;
    if (auto error = world.reset(scene)) {
        m.problem = toString(*error);
        return m;
    }
    std::size_t next = 0;
    while (next < order.size()) {
        const std::int64_t step = rows[order[next]].step;
        while (world.stepCount() < step && !world.halted())
            world.step();
        if (world.halted()) {
            m.problem = "the reference stopped after " + std::to_string(world.stepCount()) + " steps: " +
                        *world.halted();
            return m;
        }
        const BallState& b = world.balls();
        for (; next < order.size() && rows[order[next]].step == step; ++next) {
            const StudentRow& r = rows[order[next]];
            if (r.ball < 0 || r.ball >= b.size()) {
                m.problem = "line " + std::to_string(r.line) + ": ball " + std::to_string(r.ball) +
                            " is not in the reference at step " + std::to_string(step) + " (it has " +
                            std::to_string(b.size()) + " balls, numbered from 0)";
                return m;
            }
            const std::pair<const char*, std::pair<std::optional<double>, double>> fields[] = {
                {"x", {r.x, b.position(0, r.ball)}},
                {"y", {r.y, b.position(1, r.ball)}},
                {"vx", {r.vx, b.velocity(0, r.ball)}},
                {"vy", {r.vy, b.velocity(1, r.ball)}},
            };
            for (const auto& [name, values] : fields) {
                if (!values.first)
                    continue;
                const double size = std::abs(*values.first - values.second);
                if (!(size <= tolerance * std::max(1.0, std::abs(values.second)))) {
                    m.departure = Departure{step, r.ball, name, *values.first, values.second, size, r.line};
                    return m;
                }
                m.largestAgreeing = std::max(m.largestAgreeing, size);
            }
            ++m.rowsAgreeing;
        }
    }
    return m;
}

std::vector<std::pair<TraceVariant, Scene>> traceVariants(const Scene& scene)
{
    std::vector<std::pair<TraceVariant, Scene>> out;
    const WorldSettings& s = scene.settings;
    auto add = [&](TraceVariant v, auto change) {
        Scene changed = scene;
        change(changed.settings);
        out.emplace_back(std::move(v), std::move(changed));
    };
    // Update order: the two Euler steps differ only in which velocity moves the ball.
    if (s.time.integrator != IntegratorKind::Euler)
        add({"update order", "time.integrator=euler",
             "it moves the ball with the old velocity (x += v·dt, then v += a·dt: explicit Euler), where the "
             "lesson updates v first and moves with the new one"},
            [](WorldSettings& w) { w.time.integrator = IntegratorKind::Euler; });
    if (s.time.integrator != IntegratorKind::SemiImplicitEuler)
        add({"update order", "time.integrator=semi-implicit-euler",
             "it updates the velocity first and moves the ball with the new one (semi-implicit Euler), where the "
             "lesson uses " + std::string(toString(s.time.integrator))},
            [](WorldSettings& w) { w.time.integrator = IntegratorKind::SemiImplicitEuler; });
    // Units per frame: moving by v (px per frame) instead of v·dt.
    if (!s.time.perFrame && s.time.dt != kFrameSeconds)
        add({"units per frame", "time.per_frame=true",
             "it moves the balls by one frame's worth (1/60 s) each step whatever dt is: speeds in px per frame, "
             "not px/s × dt"},
            [](WorldSettings& w) { w.time.perFrame = true; });
    if (s.time.perFrame)
        add({"units per frame", "time.per_frame=false", "it scales by dt where the lesson moves per frame"},
            [](WorldSettings& w) { w.time.perFrame = false; });
    // Walls: the edge or the centre, and the other rules for putting a ball back.
    const bool walls = s.walls.left || s.walls.right || s.walls.top || s.walls.bottom || s.walls.middle;
    if (walls) {
        add({"wall rule", std::string("world.centre_only=") + (s.walls.centreOnly ? "false" : "true"),
             s.walls.centreOnly ? "it tests the ball's edge against the wall, where the lesson tests the centre"
                                : "it tests the ball's centre against the wall, not its edge"},
            [](WorldSettings& w) { w.walls.centreOnly = !w.walls.centreOnly; });
        const auto names = wallModelNames();
        for (std::size_t k = 0; k < names.size(); ++k) {
            const auto model = static_cast<WallModel>(k);
            if (model == s.walls.model)
                continue;
            add({"wall rule", "world.wall_model=" + std::string(names[k]),
                 "it puts a ball that crossed a wall back by the " + std::string(names[k]) + " rule, not the " +
                     std::string(names[static_cast<std::size_t>(s.walls.model)]) + " rule"},
                [model](WorldSettings& w) { w.walls.model = model; });
        }
    }
    // Push-apart: the contact solver's extra passes under gravity.
    if (s.collisions.response == Response::Impulse2D && s.collisions.resting)
        add({"push-apart", "models.collisions.resting=false",
             "it resolves each contact once (the textbook pass) without the passes that push a pile's balls apart"},
            [](WorldSettings& w) { w.collisions.resting = false; });
    // The course's own bugs (issue #37, part 5).
    if (s.drag.enabled && s.drag.scale != ForceScale::None)
        add({"drag scaling", "models.drag.scale=none",
             "it uses the tutorial's unscaled drag, a = −k v for every ball whatever its mass"},
            [](WorldSettings& w) { w.drag.scale = ForceScale::None; });
    if (s.randomAccel.enabled && !s.randomAccel.uncentred)
        add({"un-centred random numbers", "models.random_accel.uncentred=true",
             "it draws the random acceleration with Math.random() × strength, in [0, strength), not centred on 0"},
            [](WorldSettings& w) { w.randomAccel.uncentred = true; });
    if (s.point.enabled && !s.point.unnormalised)
        add({"un-normalised repulsion", "models.point.unnormalised=true",
             "it multiplies the difference vector d by S / d² without making it a unit vector, so |a| = S / d"},
            [](WorldSettings& w) { w.point.unnormalised = true; });
    return out;
}

std::optional<Diagnosis> diagnose(const Scene& scene, const std::vector<StudentRow>& rows, double tolerance,
                                  const TraceMatch& reference)
{
    std::optional<Diagnosis> best;
    for (auto& [variant, changed] : traceVariants(scene)) {
        TraceMatch m = matchTrace(changed, rows, tolerance);
        if (m.problem || m.rowsAgreeing <= reference.rowsAgreeing)
            continue;
        const bool better = !best || m.rowsAgreeing > best->match.rowsAgreeing ||
                            (m.rowsAgreeing == best->match.rowsAgreeing &&
                             m.largestAgreeing < best->match.largestAgreeing);
        if (better)
            best = Diagnosis{variant, std::move(m)};
    }
    return best;
}

std::string usualCauses()
{
    return "the usual causes: update order (position moved with the old velocity), the wall rule (centre or edge, "
           "clamp or mirror), push-apart of touching balls, units per frame (v added per frame, not v·dt), "
           "a different dt, seed or starting state";
}

} // namespace forcelab::sim
