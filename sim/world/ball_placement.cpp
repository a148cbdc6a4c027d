#include "sim/world/ball_placement.h"

#include "sim/world/number_text.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {

namespace {

// Pushes p inside the walls that are on. False (with `why`) when the ball
// cannot fit between two of them.
bool keepInsideWalls(Vec2& p, double radius, const WorldSettings& s, std::string& why)
{
    const WallSettings& w = s.walls;
    const double reach = w.centreOnly ? 0.0 : radius; // how far the ball's edge is from what the wall tests
    const double width = s.box.width;
    const double height = s.box.height;
    double low = w.left ? reach : -INFINITY;
    double high = w.right ? width - reach : INFINITY;
    if (w.middle) {
        if (p.x() < 0.5 * width)
            high = std::min(high, 0.5 * width - reach);
        else
            low = std::max(low, 0.5 * width + reach);
    }
    if (low > high) {
        why = "a ball of radius " + numberText(radius) + " px does not fit between the walls";
        return false;
    }
    p.x() = std::clamp(p.x(), low, high);
    const double top = w.top ? reach : -INFINITY;
    const double bottom = w.bottom ? height - reach : INFINITY;
    if (top > bottom) {
        why = "a ball of radius " + numberText(radius) + " px does not fit between the top and bottom walls (" +
              numberText(height) + " px apart)";
        return false;
    }
    p.y() = std::clamp(p.y(), top, bottom);
    return true;
}

} // namespace

Placement placeBall(const BallState& balls, const WorldSettings& settings, Vec2 wanted, double radius, int ignore)
{
    Placement result;
    if (!std::isfinite(wanted.x()) || !std::isfinite(wanted.y())) {
        result.why = "the position is not a finite number";
        return result;
    }
    Vec2 p = wanted;
    if (!keepInsideWalls(p, radius, settings, result.why))
        return result;
    // Flag only marks touching balls: they pass through each other, so overlap is allowed.
    const bool collide =
        settings.collisions.response != Response::None && settings.collisions.response != Response::Flag;
    constexpr int kPasses = 32;
    int overlapped = -1;
    for (int pass = 0; collide && pass < kPasses; ++pass) {
        overlapped = -1;
        for (int j = 0; j < balls.size(); ++j) {
            if (j == ignore)
                continue;
            const Vec2 centre = balls.position.col(j);
            const double need = (radius + balls.radius[j]) * (1.0 + kTouchingGap);
            const Vec2 d = p - centre;
            const double distance = d.norm();
            if (distance >= need)
                continue;
            overlapped = j;
            // Out along the line of centres (to the right when the centres coincide).
            const Vec2 away = distance > 0.0 ? Vec2(d / distance) : Vec2(1.0, 0.0);
            p = centre + away * need;
            if (!keepInsideWalls(p, radius, settings, result.why))
                return result;
        }
        if (overlapped < 0)
            break;
    }
    if (overlapped >= 0) {
        result.why = "no free place near here: it would overlap ball " + std::to_string(overlapped);
        return result;
    }
    result.ok = true;
    result.position = p;
    result.moved = p != wanted;
    return result;
}

} // namespace forcelab::sim
