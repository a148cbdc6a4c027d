// The response models dispatched at run time (response.h).

#include "sim/collision/response/response.h"

namespace forcelab::sim {

bool respond(Response model, double e, const Vec2& d, const Vec2& n, double wa, double wb, Vec2& va, Vec2& vb)
{
    switch (model) {
    case Response::None:
        return respondAs<Response::None>(e, d, n, wa, wb, va, vb);
    case Response::Flag:
        return respondAs<Response::Flag>(e, d, n, wa, wb, va, vb);
    case Response::Reverse1D:
        return respondAs<Response::Reverse1D>(e, d, n, wa, wb, va, vb);
    case Response::Elastic1D:
        return respondAs<Response::Elastic1D>(e, d, n, wa, wb, va, vb);
    case Response::Axis2D:
        return respondAs<Response::Axis2D>(e, d, n, wa, wb, va, vb);
    case Response::Impulse2D:
        return respondAs<Response::Impulse2D>(e, d, n, wa, wb, va, vb);
    }
    return false;
}

} // namespace forcelab::sim
