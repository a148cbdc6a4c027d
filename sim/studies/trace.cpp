#include "sim/studies/trace.h"

#include "sim/world/world.h"

namespace forcelab::sim {

const std::vector<std::string>& traceColumns()
{
    static const std::vector<std::string> names{"step", "t",  "ball", "x", "y", "vx", "vy", "ax", "ay",
                                                "pair_tests", "contacts", "wind", "random_x", "random_y"};
    return names;
}

std::vector<TraceRow> traceRows(const World& world)
{
    const BallState& b = world.balls();
    const Matrix2X a = world.accelerations();
    const Matrix2X& random = world.randomDraws();
    const bool drew = world.stepCount() > 0 && world.settings().randomAccel.enabled;
    std::vector<TraceRow> rows;
    rows.reserve(static_cast<std::size_t>(b.size()));
    for (int i = 0; i < b.size(); ++i) {
        TraceRow r;
        r.step = world.stepCount();
        r.t = world.time();
        r.ball = i;
        r.x = b.position(0, i);
        r.y = b.position(1, i);
        r.vx = b.velocity(0, i);
        r.vy = b.velocity(1, i);
        r.ax = a(0, i);
        r.ay = a(1, i);
        if (world.stepCount() > 0) {
            r.pairTests = world.lastStep().pairsTested;
            r.contacts = world.lastStep().contacts;
        }
        r.wind = world.wind();
        if (drew && i < random.cols()) {
            r.randomX = random(0, i);
            r.randomY = random(1, i);
        }
        rows.push_back(r);
    }
    return rows;
}

} // namespace forcelab::sim
