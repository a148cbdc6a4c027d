// The momenta inset [momenta]: a panel beside the box with each ball's
// momentum p = m v drawn from the tip of the one before, and their sum from
// the first tail to the last tip. The sum is the total momentum: a collision
// between two balls changes both their arrows but not the sum.

#include "overlay_table.h"

#include "arrow.h"
#include "panel.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QList>

#include <algorithm>
#include <cmath>
#include <vector>

namespace forcelab {

namespace {

// A scale (widget px per mass·px/s) from the 1-1.5-2-3-5-7 ladder that fits
// `extent` in `region`; `scale` is kept while the chain uses between a
// quarter and all of the room.
void fitScale(double& scale, const sim::Vec2& extent, const QRectF& region)
{
    const double fit = std::min(extent.x() > 0.0 ? region.width() / extent.x() : HUGE_VAL,
                                extent.y() > 0.0 ? region.height() / extent.y() : HUGE_VAL);
    if (std::isfinite(fit) && fit > 0.0 && !(scale > 0.0 && scale <= fit && scale >= 0.25 * fit)) {
        const double want = 0.85 * fit;
        const double decade = std::pow(10.0, std::floor(std::log10(want)));
        scale = decade;
        for (double step : {1.0, 1.5, 2.0, 3.0, 5.0, 7.0})
            if (step * decade <= want)
                scale = step * decade;
    }
    if (!(scale > 0.0))
        scale = 1.0;
}

void paintMomenta(const PaintContext& c)
{
    QPainter& p = c.painter;
    const QRectF& panel = c.panels.momenta;
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    const double k = c.options.lineScale;
    const QFont font = panelFont(kTotalsPixels, k);
    drawPanel(p, panel, font, {QCoreApplication::translate("Overlay", "momenta  p = m v")}, {}, k);
    const QFontMetricsF fm(font);
    const double pad = 8.0 * k;
    // Below the title: the chain of arrows and their sum.
    const QRectF region = panel.adjusted(pad, pad + fm.lineSpacing(), -pad, -pad);
    std::vector<sim::Vec2>& momenta = c.frame.momenta;
    momenta.resize(static_cast<std::size_t>(n));
    sim::Vec2 sum(0, 0);
    // The chain's corners: every partial sum (with the origin), so the
    // diagram is fitted to the room it takes, whichever way it points.
    sim::Vec2 lo(0, 0), hi(0, 0);
    const bool chain = n <= WorldPainter::kMaxMomentumChain;
    for (int i = 0; i < n; ++i) {
        momenta[static_cast<std::size_t>(i)] = balls.mass[i] * balls.velocity.col(i);
        sum += momenta[static_cast<std::size_t>(i)];
        if (chain) {
            lo = lo.cwiseMin(sum);
            hi = hi.cwiseMax(sum);
        }
    }
    lo = lo.cwiseMin(sum);
    hi = hi.cwiseMax(sum);
    c.frame.momentumSum = sum;
    double& scale = c.momentumScale;
    fitScale(scale, hi - lo, region);
    c.frame.momentumScale = scale;
    const sim::Vec2 middle = 0.5 * (lo + hi);
    const QPointF origin = region.center() - QPointF(middle.x() * scale, middle.y() * scale);
    auto to = [&](const sim::Vec2& v) { return origin + QPointF(v.x() * scale, v.y() * scale); };
    p.save();
    p.setClipRect(panel, Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, true);
    const double head = 7.0 * k;
    sim::Vec2 tail(0, 0);
    if (chain) {
        for (int i = 0; i < n; ++i) {
            const sim::Vec2 tip = tail + momenta[static_cast<std::size_t>(i)];
            QList<QLineF> lines;
            appendArrow(lines, to(tail), to(tip), head);
            p.setPen(QPen(QColor::fromRgb(balls.color[static_cast<std::size_t>(i)]).darker(115), 2.0 * k,
                          Qt::SolidLine, Qt::RoundCap));
            p.drawLines(lines);
            tail = tip;
        }
        c.frame.momentumChainTip = to(tail);
    }
    QList<QLineF> lines;
    appendArrow(lines, origin, to(sum), head);
    c.frame.momentumSumArrow = QLineF(origin, to(sum));
    p.setPen(QPen(QColor::fromRgb(canvas_colors::kForce), 3.0 * k, Qt::SolidLine, Qt::RoundCap));
    p.drawLines(lines);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor::fromRgb(canvas_colors::kForce));
    p.drawEllipse(origin, 2.5 * k, 2.5 * k);
    p.restore();
}

} // namespace

OverlayInfo momentaOverlay()
{
    // The layout gives the inset a place when the overlay is on and there are balls.
    return {.name = "momenta",
            .on = [](const PaintContext& c) { return !c.panels.momenta.isEmpty(); },
            .paint = &paintMomenta,
            .panel = true};
}

} // namespace forcelab
