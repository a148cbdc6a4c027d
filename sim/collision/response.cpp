#include "response.h"

#include <cmath>

namespace forcelab::sim {
namespace {

// A pair whose inverse masses do not add up to a positive finite number (two
// immovable balls, or a broken mass) cannot be resolved.
bool resolvable(double wa, double wb)
{
    const double w = wa + wb;
    return w > 0.0 && std::isfinite(w);
}

// The 1D impulse on one axis; u is the relative velocity b − a on it.
void impulse1D(double e, double wa, double wb, double& ua, double& ub)
{
    const double j = -(1.0 + e) * (ub - ua) / (wa + wb);
    ua -= wa * j;
    ub += wb * j;
}

} // namespace

bool reverse1D(const Vec2& d, Vec2& va, Vec2& vb)
{
    if (!((vb.x() - va.x()) * d.x() < 0.0))
        return false;
    va.x() = -va.x();
    vb.x() = -vb.x();
    return true;
}

bool elastic1D(double e, const Vec2& d, double wa, double wb, Vec2& va, Vec2& vb)
{
    if (!((vb.x() - va.x()) * d.x() < 0.0) || !resolvable(wa, wb))
        return false;
    impulse1D(e, wa, wb, va.x(), vb.x());
    return true;
}

bool axis2D(double e, const Vec2& d, double wa, double wb, Vec2& va, Vec2& vb)
{
    if (!resolvable(wa, wb))
        return false;
    bool changed = false;
    for (int k = 0; k < 2; ++k) {
        if ((vb[k] - va[k]) * d[k] < 0.0) {
            impulse1D(e, wa, wb, va[k], vb[k]);
            changed = true;
        }
    }
    return changed;
}

bool impulse2D(double e, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb)
{
    const double vn = (vb - va).dot(n);
    if (!(vn < 0.0) || !resolvable(wa, wb))
        return false;
    const double j = -(1.0 + e) * vn / (wa + wb);
    va -= (wa * j) * n;
    vb += (wb * j) * n;
    return true;
}

bool respond(Response model, double e, const Vec2& d, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb)
{
    switch (model) {
    case Response::None:
    case Response::Flag:
        return false;
    case Response::Reverse1D:
        return reverse1D(d, va, vb);
    case Response::Elastic1D:
        return elastic1D(e, d, wa, wb, va, vb);
    case Response::Axis2D:
        return axis2D(e, d, wa, wb, va, vb);
    case Response::Impulse2D:
        return impulse2D(e, n, wa, wb, va, vb);
    }
    return false;
}

} // namespace forcelab::sim
