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
//    only: velocities are never changed by it. (One-stage solve only.)
// 6. Stages (the default; `stages` > 1, after Box2D v3's soft step). Points
//    2 and 5 together still leave a pile jittering at 2-3 px/s at 60 Hz: the
//    passes cannot carry a push through a 40-ball stack within one sub-step,
//    overlap comes back every sub-step, and the correction, which moves
//    balls without telling their velocities, shuffles them sideways into
//    gaps they then fall into. So the contacts, found once per sub-step, are
//    solved in `stages` stages of hs = h / stages. The bodies start where
//    they were at the start of the sub-step with the speed they had then;
//    each stage gives them g·hs of speed, applies every contact's impulse
//    again (warm start), runs `stagePasses` passes, moves them by v·hs and
//    runs `relaxPasses` passes more. A gap now is the gap at the start plus
//    what the two bodies moved along the line of impact since. An overlap
//    is pushed apart by a soft contact: a spring at `contactStiffness` times
//    the stage rate, damped at `dampingRatio` of critical, solved implicitly
//    over the stage, so it never overshoots; the passes after the move drop
//    that push from the velocities, so what it did to the positions stays
//    and its speed does not. No positional correction runs. The bounces of
//    point 1 come after the last stage, at e times the speed each pair
//    hit with in the stage where it met (not the speed at the end of the
//    sub-step, which has up to g·h more in it); `bouncePasses` passes over
//    every row follow, and a bounce adds velocityPasses − bouncePasses more
//    over the rows within `bounceLayers` balls of it. A ball that hits the
//    pile in an early stage gets the same extra passes, rigid, in every
//    stage from then on, and in the passes after a bounce a row that pushed
//    in this sub-step holds even across a hair of gap, so the pile under a
//    struck ball does not yield and the ball bounces as from a floor. A new
//    contact's speed at the end counts a ball that contacts held in the
//    last solve as not falling (they take its g·h out again). Gravity in short
//    stages is what the pile needs: the overlap one of 6 stages makes is
//    1/36 of a whole step's. A body no contact pushed keeps the
//    integrator's result, so a lone ball (a restitution-1 ball bouncing for
//    ever) moves exactly as without the solver.
// 7. Sleeping (staged solve; Box2D puts resting islands to sleep). A pile
//    at rest still costs every pass of point 6 in every step. A ball that
//    contacts have held for `sleepTime`, slower than stillShare · v_rest all
//    that time, with every ball near it as still, goes to sleep: it stays
//    where it is at speed 0, and to the balls still awake it is a ball of
//    infinite mass. Rows between two sleepers are not solved at all (their
//    impulses are kept for when they wake). Before the solve, a pair that
//    approaches faster than stillShare · v_rest with one ball asleep (a
//    push on a sleeper), or faster than wakeShare · v_rest with both awake
//    (a ball landing on the pile's surface), wakes every sleeper within
//    `wakeLayers` balls of it, so a ball dropped on a sleeping pile meets a
//    pile that gives as an awake one does. Awake balls jittering on a
//    sleeping pile approach each other at a few px/s, below wakeShare, so
//    they do not keep waking it. Any edit between steps wakes
//    every ball, and balls sleep only while every force on a ball at rest
//    depends on where it is alone (gravity, drag, point force, spring,
//    homing, magnetic field; not wind, the pointer, random kicks, mutual
//    gravity or a custom force), so a sleeper would feel the same force as
//    when it fell asleep. A world whose every ball has slept through a
//    whole step skips its sub-steps until something wakes a ball
//    (CollisionSystem::everyBallSleeps): each would put every ball back
//    where it is and find the same pairs.
// 8. Islands (staged solve; contact_islands.h). Points 1-7 are for piles,
//    and a gas under gravity has none: its balls meet now and then, fast.
//    The pairs that may push this sub-step (they overlap, close their gap
//    within it or within what gravity closes on a held ball, |g|·h², or
//    pushed in the last one) join their balls into islands. An island needs
//    the solver when one of its pairs meets slower than v_rest, meets a
//    ball held in the last solve or pushed in the last sub-step, or one of
//    its balls is near a wall, asleep or of infinite mass; an island next
//    to one that needs it, across a pair that does not meet, is taken too. Only those islands get rows, bodies and
//    passes. In the free islands each pair that meets gets the exact
//    impulse of two free balls at the moment it meets (free_impacts.h),
//    and a speculative pair that does not meet costs nothing after the
//    broad phase. A standing pile is an island that needs the solver, and
//    it is solved as before. When every force gives every ball the same
//    acceleration (gravity alone; ForceModelInfo::sameForEveryBall), an
//    island needs the solver only through an anchor: a ball near a wall,
//    asleep or of infinite mass. Without one the island falls as one, and
//    nothing presses its balls together: a slow pair in it (balls spawned
//    overlapping, two balls that drift into each other in mid-air) is a
//    slow impact, and bounces at e, not at 0 as a resting pair would.

namespace forcelab::sim {

struct ContactSolverSettings {
    int velocityPasses = 30;      ///< 1, most velocity passes per sub-step, before and again after the bounces are set
    double restingFactor = 2.0;   ///< 1, c in v_rest = c·|g|·h; approaches slower than v_rest do not bounce
    double relaxTolerance = 0.001; ///< 1, stop the passes when no pair approaches faster than this × v_rest
    double slop = 0.005;          ///< 1, allowed overlap as a share of the smaller radius
    double correction = 0.8;      ///< 1, share of the overlap beyond the slop removed per position pass
    int positionPasses = 4;       ///< 1, passes of positional correction per sub-step
    double speculative = 4.0;     ///< 1, most a ball's radius grows by to find speculative contacts (0: none)
    // The staged solve (point 6), used when stages > 1.
    int stages = 6;               ///< 1, solver stages per sub-step (1: one stage with positional correction)
    int stagePasses = 4;          ///< 1, velocity passes per stage that also push overlaps apart
    int relaxPasses = 1;          ///< 1, velocity passes per stage after the move, without the push
    int bouncePasses = 4;         ///< 1, passes after the last stage over every row (velocityPasses when a pair bounces)
    int bounceLayers = 12;        ///< 1, staged solve: the passes a bounce adds go to the rows this many balls from it (0: every row)
    int impactRows = 4096;        ///< 1, staged solve: most rows that get a stage's impact passes over every row, when the region around the impact is half the pile or more
    double contactStiffness = 0.5; ///< 1, a soft contact's spring frequency as a share of the stage rate 1/hs
    double dampingRatio = 1.0;    ///< 1, the soft contact's damping as a share of critical damping
    double pushSpeed = 300.0;     ///< px/s, fastest speed at which an overlap is pushed apart
    // Sleeping (point 7), staged solve only.
    double sleepTime = 0.5;       ///< s, how long a held ball stays still before it sleeps (0: no sleeping)
    double stillShare = 0.1;      ///< 1, a ball is still while slower than stillShare × v_rest
    double wakeShare = 0.5;       ///< 1, a pair approaching faster than wakeShare × v_rest wakes the sleepers near it
    int wakeLayers = 12;          ///< 1, a pair that approaches wakes the sleepers this many balls from it
};

} // namespace forcelab::sim
