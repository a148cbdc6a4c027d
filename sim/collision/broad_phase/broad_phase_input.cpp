// The ball arrays the broad phases read (broad_phase_input.h).

#include "sim/collision/broad_phase/broad_phase_input.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab::sim {

void BroadPhaseInput::copyBalls(const BallState& balls)
{
    const int n = balls.size();
    x.resize(static_cast<std::size_t>(n));
    y.resize(static_cast<std::size_t>(n));
    r.resize(static_cast<std::size_t>(n));
    const double* p = balls.position.data(); // column-major 2×N: x0 y0 x1 y1 ...
    const double* rad = balls.radius.data();
    for (int i = 0; i < n; ++i) {
        x[static_cast<std::size_t>(i)] = p[2 * i];
        y[static_cast<std::size_t>(i)] = p[2 * i + 1];
        r[static_cast<std::size_t>(i)] = rad[i];
    }
}

void BroadPhaseInput::loadStatic(const BallState& balls, const double* grow)
{
    // One pass: copy, box, finiteness, the active list and the extremes; a
    // second one pads the boxes (the pad depends on the largest coordinate).
    const int n = balls.size();
    const auto count = static_cast<std::size_t>(n);
    x.resize(count);
    y.resize(count);
    r.resize(count);
    loX.resize(count);
    hiX.resize(count);
    loY.resize(count);
    hiY.resize(count);
    x0.clear();
    y0.clear();
    active.resize(count);
    const double* p = balls.position.data(); // column-major 2×N: x0 y0 x1 y1 ...
    const double* rad = balls.radius.data();
    double maxAbs = 0.0, maxR = 0.0, maxW = 0.0, maxH = 0.0, sumSize = 0.0;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const double px = p[2 * i], py = p[2 * i + 1], ri = grow ? rad[i] + grow[i] : rad[i];
        const double lx = px - ri, hx = px + ri, ly = py - ri, hy = py + ri;
        // Finite box and r >= 0 (a finite box means finite x, y and r);
        // v − v is 0 for a finite v and NaN otherwise.
        const bool ok = ((lx - lx) + (hx - hx) + (ly - ly) + (hy - hy)) == 0.0 && ri >= 0.0;
        x[i] = ok ? px : std::numeric_limits<double>::quiet_NaN();
        y[i] = py;
        r[i] = ri;
        loX[i] = lx;
        hiX[i] = hx;
        loY[i] = ly;
        hiY[i] = hy;
        active[kept] = static_cast<int>(i);
        kept += ok ? 1 : 0;
        if (ok) {
            maxAbs = std::max(maxAbs, std::max(std::max(std::abs(lx), std::abs(hx)), std::max(std::abs(ly), std::abs(hy))));
            maxR = std::max(maxR, ri);
            maxW = std::max(maxW, hx - lx);
            maxH = std::max(maxH, hy - ly);
            sumSize += std::max(hx - lx, hy - ly);
        }
    }
    active.resize(kept);
    pad = 1e-12 * (maxAbs + 2.0 * maxR) + std::numeric_limits<double>::min();
    for (std::size_t i = 0; i < count; ++i) {
        loX[i] -= pad;
        hiX[i] += pad;
        loY[i] -= pad;
        hiY[i] += pad;
    }
    // Sizes of the padded boxes, up to rounding (they only tune the cells and rows).
    maxWidth = maxW + 2.0 * pad;
    maxHeight = maxH + 2.0 * pad;
    meanSize = kept == 0 ? 0.0 : sumSize / static_cast<double>(kept) + 2.0 * pad;
}

void BroadPhaseInput::loadSwept(const BallState& balls, const Matrix2X& start, const double* grow)
{
    copyBalls(balls);
    if (grow)
        for (std::size_t i = 0; i < r.size(); ++i)
            r[i] += grow[i];
    const std::size_t n = x.size();
    x0.resize(n);
    y0.resize(n);
    loX.resize(n);
    hiX.resize(n);
    loY.resize(n);
    hiY.resize(n);
    const double* s = start.data();
    for (std::size_t i = 0; i < n; ++i) {
        x0[i] = s[2 * i];
        y0[i] = s[2 * i + 1];
        loX[i] = std::min(x0[i], x[i]) - r[i];
        hiX[i] = std::max(x0[i], x[i]) + r[i];
        loY[i] = std::min(y0[i], y[i]) - r[i];
        hiY[i] = std::max(y0[i], y[i]) + r[i];
    }
    finishBounds();
}

void BroadPhaseInput::finishBounds()
{
    const std::size_t n = x.size();
    const bool swept = !x0.empty();
    active.clear();
    double maxAbs = 0.0, maxR = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        bool ok = std::isfinite(x[i]) && std::isfinite(y[i]) && std::isfinite(r[i]) && r[i] >= 0.0;
        if (swept)
            ok = ok && std::isfinite(x0[i]) && std::isfinite(y0[i]);
        // The box must be finite too (x + r can overflow for absurd values).
        ok = ok && std::isfinite(loX[i]) && std::isfinite(hiX[i]) && std::isfinite(loY[i]) && std::isfinite(hiY[i]);
        if (!ok) {
            x[i] = std::numeric_limits<double>::quiet_NaN();
            if (swept)
                x0[i] = std::numeric_limits<double>::quiet_NaN();
            continue;
        }
        active.push_back(static_cast<int>(i));
        maxAbs = std::max({maxAbs, std::abs(loX[i]), std::abs(hiX[i]), std::abs(loY[i]), std::abs(hiY[i])});
        maxR = std::max(maxR, r[i]);
    }
    // Every rounding error in the narrow test and in the box edges is below a
    // few ulps of (|coordinate| + r); 1e-12 of it is a thousandfold margin.
    pad = 1e-12 * (maxAbs + 2.0 * maxR) + std::numeric_limits<double>::min();
    double sumSize = 0.0;
    maxWidth = 0.0;
    maxHeight = 0.0;
    for (const int i : active) {
        const auto k = static_cast<std::size_t>(i);
        loX[k] -= pad;
        hiX[k] += pad;
        loY[k] -= pad;
        hiY[k] += pad;
        const double w = hiX[k] - loX[k];
        const double h = hiY[k] - loY[k];
        maxWidth = std::max(maxWidth, w);
        maxHeight = std::max(maxHeight, h);
        sumSize += std::max(w, h);
    }
    meanSize = active.empty() ? 0.0 : sumSize / static_cast<double>(active.size());
}

} // namespace forcelab::sim
