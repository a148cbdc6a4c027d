#pragma once
// What happens to the velocities of two touching balls, from the naive first
// try to the impulse along the line of impact. Each function changes va and vb
// of one pair in place and returns whether it changed anything.
//
// Notation: ball a and ball b, inverse masses wa = 1/ma and wb = 1/mb, d the
// vector from a's centre to b's, n = d/|d| the line of impact, e the
// restitution. A pair that is already moving apart is left alone (otherwise a
// pair still overlapping on the next step would be pulled back together).

#include "sim/world/types.h"
#include "sim/world/world_settings.h"

#include <cmath>

namespace forcelab::sim {

namespace detail {

// A pair whose inverse masses do not add up to a positive finite number (two
// immovable balls, or a broken mass) cannot be resolved.
inline bool resolvable(double wa, double wb)
{
    const double w = wa + wb;
    return w > 0.0 && std::isfinite(w);
}

// The 1D impulse on one axis; u is the relative velocity b − a on it.
inline void impulse1D(double e, double wa, double wb, double& ua, double& ub)
{
    const double j = -(1.0 + e) * (ub - ua) / (wa + wb);
    ua -= wa * j;
    ub += wb * j;
}

} // namespace detail

/// 1d-reverse, the naive try: if the balls approach along x, negate both
/// horizontal velocities. Conserves momentum only by luck (equal masses and
/// opposite speeds); a ball at rest stays at rest.
inline bool reverse1D(const Vec2& d, Vec2& va, Vec2& vb)
{
    if (!((vb.x() - va.x()) * d.x() < 0.0))
        return false;
    va.x() = -va.x();
    vb.x() = -vb.x();
    return true;
}

/// 1d-elastic: the collision along x with both masses. With u = vb.x − va.x,
/// the impulse j = −(1 + e) u / (wa + wb) gives va.x −= wa j, vb.x += wb j:
/// momentum is conserved, u becomes −e u, and for e = 1 kinetic energy too.
/// (The same as the textbook va' = ((ma − e mb) va + (1 + e) mb vb)/(ma + mb).)
// [code response.elastic-1d if models.collisions.response=1d-elastic: A collision along x]
inline bool elastic1D(double e, const Vec2& d, double wa, double wb, Vec2& va, Vec2& vb)
{
    if (!((vb.x() - va.x()) * d.x() < 0.0) || !detail::resolvable(wa, wb))
        return false;
    detail::impulse1D(e, wa, wb, va.x(), vb.x());
    return true;
}
// [/code]

/// 2d-axis, the naive 2D try: the 1D elastic collision on x and on y
/// separately (each axis where the balls approach along it). Conserves
/// momentum and, for e = 1, energy, but an off-centre hit goes the wrong way.
// [code response.axis-2d if models.collisions.response=2d-axis: The naive 2D collision, axis by axis]
inline bool axis2D(double e, const Vec2& d, double wa, double wb, Vec2& va, Vec2& vb)
{
    if (!detail::resolvable(wa, wb))
        return false;
    bool changed = false;
    for (int k = 0; k < 2; ++k) {
        if ((vb[k] - va[k]) * d[k] < 0.0) {
            detail::impulse1D(e, wa, wb, va[k], vb[k]);
            changed = true;
        }
    }
    return changed;
}
// [/code]

/// 2d-impulse: the push acts along n only. With v_n = (vb − va)·n < 0,
///   j = −(1 + e) v_n / (wa + wb),  va −= wa j n,  vb += wb j n.
/// The normal relative speed becomes −e v_n, the tangential parts are
/// unchanged, momentum is conserved, and kinetic energy drops by exactly
/// (1 − e²) · ½ μ v_n² with μ = 1/(wa + wb) (nothing for e = 1).
// [code response.impulse-2d if models.collisions.response=2d-impulse: The collision along the line of impact]
inline bool impulse2D(double e, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb)
{
    const double vn = (vb - va).dot(n);
    if (!(vn < 0.0) || !detail::resolvable(wa, wb))
        return false;
    const double j = -(1.0 + e) * vn / (wa + wb);
    va -= (wa * j) * n;
    vb += (wb * j) * n;
    return true;
}
// [/code]

/// The response of one model, chosen at compile time (None and Flag change
/// nothing): the one place that maps a model to its function, for respond()
/// and for the contact pass of each model (collision_system.cpp).
template <Response Model>
inline bool respondAs(double e, const Vec2& d, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb)
{
    if constexpr (Model == Response::Reverse1D)
        return reverse1D(d, va, vb);
    else if constexpr (Model == Response::Elastic1D)
        return elastic1D(e, d, wa, wb, va, vb);
    else if constexpr (Model == Response::Axis2D)
        return axis2D(e, d, wa, wb, va, vb);
    else if constexpr (Model == Response::Impulse2D)
        return impulse2D(e, n, wa, wb, va, vb);
    else
        return false;
}

/// Dispatches on the model (None and Flag change nothing).
bool respond(Response model, double e, const Vec2& d, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb);

} // namespace forcelab::sim
