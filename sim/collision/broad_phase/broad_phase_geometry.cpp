// The broad phase's geometry for drawing it: grid cells, sweep rows (broad_phase_geometry.h).

#include "sim/collision/broad_phase/broad_phase_geometry.h"

#include "sim/collision/broad_phase/broad_phase_input.h"
#include "sim/collision/broad_phase/sweep_and_prune.h"
#include "sim/collision/broad_phase/uniform_grid.h"

namespace forcelab::sim {

BroadPhaseGeometry broadPhaseGeometry(const World& world)
{
    BroadPhaseGeometry g;
    const Detection detection = world.settings().collisions.detection;
    const CollisionSystem& system = world.collisionSystem();
    // The detector's last layout, once the world has stepped.
    if (world.stepCount() > 0) {
        if (detection == Detection::Grid && system.grid().cellSize() > 0.0)
            return {system.grid().cellSize(), system.grid().originX(), system.grid().originY(), 0.0};
        if (detection == Detection::Sweep && system.sweepAndPrune().rowHeight() > 0.0)
            return {0.0, 0.0, 0.0, system.sweepAndPrune().rowHeight()};
    }
    // Not stepped yet: lay out the balls where they are, as a step would.
    BroadPhaseInput in;
    in.loadStatic(world.balls());
    if (in.active.empty())
        return g;
    if (detection == Detection::Grid) {
        UniformGrid grid;
        grid.layOut(in);
        g.cellSize = grid.cellSize();
        g.originX = grid.originX();
        g.originY = grid.originY();
    } else if (detection == Detection::Sweep) {
        g.rowHeight = SweepAndPrune::rowHeightFor(in.maxHeight);
    }
    return g;
}

} // namespace forcelab::sim
