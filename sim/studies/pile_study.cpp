#include "sim/studies/pile_study.h"

#include "sim/world/threads.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace forcelab::sim {

std::vector<PileStudyRow> runPileStudy(const PileStudyOptions& o, std::ostream* out)
{
    Scene scene = peerScene(o.balls);
    scene.settings.time.substeps = o.substeps;
    scene.settings.collisions.restitution = o.restitution;
    scene.settings.walls.restitution = o.restitution;
    std::unique_ptr<ThreadLimit> limit;
    if (o.threads > 0)
        limit = std::make_unique<ThreadLimit>(o.threads);
    World world(scene);
    world.collisionSystem().setSolverSettings(o.solver);

    const double dt = scene.settings.time.dt;
    const long steps = std::lround(o.seconds / dt);
    const long stride = std::max(1L, std::lround(o.every / dt));
    if (out)
        *out << "    t s   deepest r    mean r   rms px/s   max px/s   >5 px/s   height px   pile px/s   in flight"
                "    ms/step   bounced    asleep\n";
    std::vector<PileStudyRow> rows;
    // Only the steps are timed (the world's own clock), not the measures
    // between the rows.
    double stepSeconds = 0.0;
    long stepsTimed = 0;
    int bounceSteps = 0;
    for (long s = 1; s <= steps; ++s) {
        world.step();
        stepSeconds += world.lastStep().seconds;
        ++stepsTimed;
        bounceSteps += world.collisionSystem().lastStepBounced() ? 1 : 0;
        if (s % stride != 0 && s != steps)
            continue;
        PileStudyRow row;
        row.time = static_cast<double>(s) * dt;
        row.msPerStep = 1000.0 * stepSeconds / static_cast<double>(stepsTimed);
        row.bounceSteps = bounceSteps;
        row.asleep = world.collisionSystem().sleepingCount();
        stepSeconds = 0.0;
        stepsTimed = 0;
        bounceSteps = 0;
        row.measures = measurePile(world);
        const BallState& b = world.balls();
        for (int i = 0; i < b.size(); ++i) {
            const double speed = b.velocity.col(i).norm();
            row.maxSpeed = std::max(row.maxSpeed, speed);
            row.movingBalls += speed > 5.0 ? 1 : 0;
        }
        rows.push_back(row);
        if (out) {
            char line[220];
            std::snprintf(line, sizeof line, "%7.2f %11.3f %9.4f %10.2f %10.1f %9d %11.1f %11.2f %11d %10.2f %9d %9d\n",
                          row.time, row.measures.deepestOverlap, row.measures.meanOverlap, row.measures.rmsSpeed,
                          row.maxSpeed, row.movingBalls, row.measures.meanHeight, row.measures.pileRmsSpeed,
                          row.measures.inFlight, row.msPerStep, row.bounceSteps, row.asleep);
            *out << line << std::flush;
        }
    }
    return rows;
}

} // namespace forcelab::sim
