#pragma once
// Resting contact: how 2d-impulse keeps a pile of balls standing under gravity.
//
// One pass of impulses per sub-step is right for balls that meet now and then
// (a gas, a break shot), but a pile is different: every sub-step gravity adds
// g·h of speed to every ball, so every ball pushes on the ones below it, and
// the push has to reach the floor within the sub-step. One pass moves it one
// ball down at most; the rest of the pile sinks into itself, positional
// correction lifts it again (adding height, and so energy), and the pile
// heats up and collapses into a much denser heap than real balls make.
//
// The standard cure (Box2D and most game engines), used when gravity is on:
//
// 1. Restitution threshold. A pair that approaches slower than
//      v_rest = c · |g| · h      (c = restingFactor, about 2)
//    is resting, not colliding: gravity alone made that speed in the last
//    sub-step or two. It gets restitution 0 instead of e, so a resting ball
//    does not bounce on the ball below it forever. v_rest is 0 when gravity is
//    off: scenes without gravity keep the textbook one-pass step exactly.
// 2. Sequential impulses. Several velocity passes over the contacts (in the
//    same order every time, so a run is repeatable) stop every pair that
//    approaches faster than it may (target normal speed 0, or −gap/h for a
//    speculative contact), so a push travels down a pile a few balls per pass.
//    After the first pass a contact is solved again only if one of its
//    balls changed speed by more than relaxTolerance · v_rest since; the
//    passes stop early once no ball did. Then restitution: a new contact
//    (no push in the last sub-step) that hit faster than v_rest gets the
//    target e times the speed it hit with, and the passes run again over all
//    contacts, so a pile holds while a ball bounces off it.
// 3. The walls take part. A ball on an enabled wall (or so close that one
//    sub-step of gravity would bring it there) is a contact with a partner of
//    infinite mass: the passes stop it from moving into the wall faster than
//    it can close the gap in one sub-step. A ball the wall stage has just
//    bounced off a wall (clamp leaves it exactly on the wall) has that bounce
//    taken back: the solver bounces it with the others, at e_w if it came
//    faster than v_rest, so a floor ball under a pile does not hop every step.
// 4. Speculative contacts. A pair that does not touch yet but is closer than
//    one sub-step of motion can close (each ball's radius grown by
//    |v − u|·h + |g|·h², u the mean velocity of the balls around it, at most
//    `speculative` of its radius: speculative_margin.h) is a contact too,
//    one that may close its gap but no more: its normal speed may not drop
//    below −gap/h. Line of impact and gap are taken at the start of the
//    sub-step (the centres less (v_b − v_a)·h), where a fast ball is not yet
//    inside the one it hits. A ball landing on a pile then stops on it
//    instead of sinking into it, and a column standing at touching distance
//    holds. contacts() and the counters still report only pairs that overlap.
// 5. Positional correction with slop. Overlap up to slop · (smaller radius)
//    is allowed, and only `correction` of the overlap beyond it is removed in
//    each of the `positionPasses` passes. A resting pair then sits still at a tiny overlap instead of
//    being pushed apart and falling back every sub-step (jitter). Positions
//    only: velocities are never changed by it.

namespace forcelab::sim {

struct ContactSolverSettings {
    int velocityPasses = 30;      ///< 1, most velocity passes per sub-step, before and again after the bounces are set
    double restingFactor = 2.0;   ///< 1, c in v_rest = c·|g|·h; approaches slower than v_rest do not bounce
    double relaxTolerance = 0.001; ///< 1, stop the passes when no pair approaches faster than this × v_rest
    double slop = 0.005;          ///< 1, allowed overlap as a share of the smaller radius
    double correction = 0.8;      ///< 1, share of the overlap beyond the slop removed per position pass
    int positionPasses = 4;       ///< 1, passes of positional correction per sub-step
    double speculative = 4.0;     ///< 1, most a ball's radius grows by to find speculative contacts (0: none)
};

} // namespace forcelab::sim
