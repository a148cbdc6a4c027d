#pragma once
// What happens to the velocities of two touching balls, from the naive first
// try to the impulse along the line of impact. Each function changes va and vb
// of one pair in place and returns whether it changed anything.
//
// Notation: ball a and ball b, inverse masses wa = 1/ma and wb = 1/mb, d the
// vector from a's centre to b's, n = d/|d| the line of impact, e the
// restitution. A pair that is already moving apart is left alone (otherwise a
// pair still overlapping on the next step would be pulled back together).

#include "../types.h"
#include "../world_settings.h"

namespace forcelab::sim {

/// 1d-reverse, the naive try: if the balls approach along x, negate both
/// horizontal velocities. Conserves momentum only by luck (equal masses and
/// opposite speeds); a ball at rest stays at rest.
bool reverse1D(const Vec2& d, Vec2& va, Vec2& vb);

/// 1d-elastic: the collision along x with both masses. With u = vb.x − va.x,
/// the impulse j = −(1 + e) u / (wa + wb) gives va.x −= wa j, vb.x += wb j:
/// momentum is conserved, u becomes −e u, and for e = 1 kinetic energy too.
/// (The same as the textbook va' = ((ma − e mb) va + (1 + e) mb vb)/(ma + mb).)
bool elastic1D(double e, const Vec2& d, double wa, double wb, Vec2& va, Vec2& vb);

/// 2d-axis, the naive 2D try: the 1D elastic collision on x and on y
/// separately (each axis where the balls approach along it). Conserves
/// momentum and, for e = 1, energy, but an off-centre hit goes the wrong way.
bool axis2D(double e, const Vec2& d, double wa, double wb, Vec2& va, Vec2& vb);

/// 2d-impulse: the push acts along n only. With v_n = (vb − va)·n < 0,
///   j = −(1 + e) v_n / (wa + wb),  va −= wa j n,  vb += wb j n.
/// The normal relative speed becomes −e v_n, the tangential parts are
/// unchanged, momentum is conserved, and kinetic energy drops by exactly
/// (1 − e²) · ½ μ v_n² with μ = 1/(wa + wb) (nothing for e = 1).
bool impulse2D(double e, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb);

/// Dispatches on the model (None and Flag change nothing).
bool respond(Response model, double e, const Vec2& d, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb);

} // namespace forcelab::sim
