#include "sim/collision/response/response.h"


namespace forcelab::sim {

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
