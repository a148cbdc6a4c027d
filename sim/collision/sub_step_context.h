#pragma once
// What every stage of the resting-contact solver reads about the sub-step it
// works in: its length, the box and its walls, the restitution, the speed
// below which a contact rests, gravity and the solver's tuning. Built once
// per sub-step by CollisionSystem::step, passed to each stage whole.

#include "../world_settings.h"
#include "contact_solver.h"

namespace forcelab::sim {

struct SubStepContext {
    double h = 0.0;               ///< s, the length of the sub-step
    double inverseH = 0.0;        ///< 1/s, 1/h
    BoxSettings box;              ///< the box the walls bound
    WallSettings walls;           ///< which walls are on, their restitution
    double restitution = 1.0;     ///< 1, ball–ball restitution e
    double restingSpeed = 0.0;    ///< px/s, v_rest = restingFactor·|g|·h: slower approaches rest instead of bouncing
    double gravity = 0.0;         ///< px/s², |g|
    double gravityX = 0.0;        ///< px/s², g along x (the staged solve adds g·h/stages per stage)
    double gravityY = 0.0;        ///< px/s², g along y
    ContactSolverSettings solver; ///< passes, slop, correction, tolerances
};

} // namespace forcelab::sim
