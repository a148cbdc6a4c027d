#pragma once
// What every stage of the resting-contact solver reads about the sub-step it
// works in: its length, the box and its walls, the restitution, the speed
// below which a contact rests, gravity and the solver's tuning. Built once
// per sub-step by CollisionSystem::step, passed to each stage whole.

#include "sim/world/world_settings.h"
#include "sim/collision/resting/contact_solver.h"

namespace forcelab::sim {

struct SubStepContext {
    double h = 0.0;               ///< s, the length of the sub-step
    double inverseH = 0.0;        ///< 1/s, 1/h
    BoxSettings box;              ///< the box the walls bound
    WallSettings walls;           ///< which walls are on, their restitution
    double restitution = 1.0;     ///< 1, ball–ball restitution e
    /// 1, per ball, its own restitution or kWorldRestitution (ball_state.h);
    /// nullptr when no ball has one: restitution and walls.restitution hold for all
    const double* ownRestitution = nullptr;
    double restingSpeed = 0.0;    ///< px/s, v_rest = restingFactor·|g|·h: slower approaches rest instead of bouncing
    double gravity = 0.0;         ///< px/s², |g|
    double gravityX = 0.0;        ///< px/s², g along x (the staged solve adds g·h/stages per stage)
    double gravityY = 0.0;        ///< px/s², g along y
    ContactSolverSettings solver; ///< passes, slop, correction, tolerances
    /// 1, the staged solve starts a body at x − v·h + startLag · g · h²
    /// (x, v where the integrator left it). Explicit Euler moves by its old
    /// velocity, so x − v·h misses its start by g·h²: 1 for it; without it
    /// its piles never came to rest and a ball dropped on one rose 2-25% of
    /// e²·h0. 0 for semi-implicit Euler, which moves by its new velocity. The
    /// integrators that follow the parabola miss by ½ g·h², which is left:
    /// taken back, the wall rows let a lone e = 1 ball under exact walls lose
    /// energy (restitutionOneKeepsEnergyWithTheSolver), and their piles stand
    /// and bounce as well without it.
    double startLag = 0.0;
    /// Every force acting gives every ball the same acceleration (gravity
    /// alone): an island with no anchor falls as one (contact_islands.h).
    bool sameForce = false;
};

} // namespace forcelab::sim
