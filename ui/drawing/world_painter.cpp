// WorldPainter: lays out the box and its panels, fills the letterbox and the
// box, and walks the table of overlays (overlays/overlay_table.h) in order.
// The panels' text and the scales the arrows share are built here, so the
// canvas, the stage bar and the tests read the same numbers.

#include "world_painter.h"

#include "display_units.h"
#include "human_number.h"
#include "panel_layout.h"
#include "overlays/overlay_table.h"

#include "sim/forces/force_models.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace forcelab {

Overlays Overlays::fromNames(const QStringList& names)
{
    Overlays o;
    o.velocity = names.contains(QStringLiteral("velocity"));
    o.acceleration = names.contains(QStringLiteral("acceleration"));
    o.readout = names.contains(QStringLiteral("readout"));
    o.colliding = names.contains(QStringLiteral("colliding"));
    o.trails = names.contains(QStringLiteral("trails"));
    o.forces = names.contains(QStringLiteral("forces"));
    o.forceSources = names.contains(QStringLiteral("sources"));
    o.centreOfMass = names.contains(QStringLiteral("centre-of-mass"));
    o.momenta = names.contains(QStringLiteral("momenta"));
    o.apexes = names.contains(QStringLiteral("apexes"));
    o.vanes = names.contains(QStringLiteral("vanes"));
    o.impact = names.contains(QStringLiteral("impact"));
    o.broadphase = names.contains(QStringLiteral("broadphase"));
    o.histogram = names.contains(QStringLiteral("histogram"));
    o.totals = names.contains(QStringLiteral("totals"));
    // ghost stays on: it draws only while a ghost world runs.
    return o;
}

ViewTransform WorldPainter::view(const sim::World& world, const QRectF& area, const PaintOptions& options)
{
    return ViewTransform::fit(world.settings().box, layoutPanels(world, area, options).stage, options.margin,
                              options.camera);
}

WorldPainter::Panels WorldPainter::panels(const sim::World& world, const QRectF& area, const PaintOptions& options)
{
    return layoutPanels(world, area, options).panels;
}

void WorldPainter::paint(QPainter& p, const QRectF& area, const sim::World& world, const PaintOptions& options,
                         qreal dpr)
{
    // One layout for the frame: where the box goes and where its panels go.
    const PanelLayout layout = layoutPanels(world, area, options);
    m_frame = PaintedFrame();
    const ViewTransform v = ViewTransform::fit(world.settings().box, layout.stage, options.margin, options.camera);
    PaintContext context{p,        area,    v,       world, options, layout.panels, dpr, m_sprites,
                         m_paths, m_frame, m_momentumScale};
    p.save();
    p.setClipRect(area);
    p.fillRect(area, QColor::fromRgb(colorsOf(options).letterbox));
    // A zoomed or moved view keeps the world in the stage, out of the panels' strip.
    const QRectF worldClip = v.moved() ? layout.stage : area;
    p.fillRect(v.boxRect().intersected(worldClip), QColor::fromRgb(colorsOf(options).background));
    // The accelerations are worked out once, for the first overlay that needs them.
    std::optional<sim::Matrix2X> accelerations;
    for (const OverlayInfo& overlay : overlayTable()) {
        if (!overlay.on(context))
            continue;
        if (!accelerations && overlay.needsAccelerations && overlay.needsAccelerations(options) &&
            !world.balls().empty()) {
            accelerations = world.accelerations();
            context.accelerations = &*accelerations;
        }
        p.setClipRect(overlay.panel ? area : worldClip);
        overlay.paint(context);
    }
    p.restore();
}

namespace {

// The median of the nonzero lengths of the columns of m (0 when none).
double medianLength(const sim::Matrix2X& m)
{
    std::vector<double> lengths;
    lengths.reserve(static_cast<std::size_t>(m.cols()));
    for (Eigen::Index i = 0; i < m.cols(); ++i) {
        const double l = m.col(i).norm();
        if (l > 0.0 && std::isfinite(l))
            lengths.push_back(l);
    }
    if (lengths.empty())
        return 0.0;
    const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), mid, lengths.end());
    return *mid;
}

} // namespace

WorldPainter::ArrowScales WorldPainter::arrowScales(const sim::World& world, const ViewTransform& view,
                                                    const PaintOptions& options, const sim::Matrix2X* accelerations)
{
    const double f = options.arrowFactor > 0.0 ? options.arrowFactor : 1.0;
    ArrowScales s{f * options.velocityScale, f * options.accelerationScale, f * options.forceScale};
    if (!options.autoArrows || !(view.scale() > 0.0))
        return s;
    // A scale of k seconds draws a speed v as k v world px, k v scale screen px.
    // A scale fixed earlier in the run is kept; one fixed now is stored.
    ArrowRun* run = options.arrowRun;
    const double factor = run && run->factor > 0.0 ? run->factor : 1.0;
    const auto fix = [&](double ArrowRun::*member, double median, double& out) {
        double fixed = run ? run->*member : 0.0;
        if (!(fixed > 0.0) && median > 0.0) {
            fixed = kArrowPixels / (view.scale() * median);
            if (run)
                run->*member = fixed;
        }
        if (fixed > 0.0)
            out = factor * fixed;
    };
    fix(&ArrowRun::velocity, medianLength(world.balls().velocity), s.velocity);
    fix(&ArrowRun::acceleration, accelerations ? medianLength(*accelerations) : 0.0, s.acceleration);
    if (accelerations && (options.overlays.forces || options.overlays.forceSources)) {
        // The net forces m a set the scale; the per-source arrows share it.
        sim::Matrix2X forces = *accelerations;
        const sim::BallState& balls = world.balls();
        for (Eigen::Index i = 0; i < forces.cols() && i < balls.size(); ++i)
            forces.col(i) *= balls.mass[static_cast<int>(i)];
        fix(&ArrowRun::force, medianLength(forces), s.force);
    } else if (run && run->force > 0.0) {
        s.force = factor * run->force;
    }
    return s;
}

QColor WorldPainter::sourceColor(std::string_view name)
{
    // The Okabe-Ito colours (safe for the common colour-vision
    // deficiencies), with the yellow darkened to show on white and without
    // the black of the net force arrow.
    static constexpr QRgb kColors[] = {0xff0072b2, 0xffd55e00, 0xff009e73, 0xffcc79a7,
                                       0xff56b4e9, 0xffe69f00, 0xffa89a00};
    std::size_t k = 0;
    for (const sim::ForceModelInfo& m : sim::forceModels()) {
        if (m.name == name)
            break;
        ++k;
    }
    return QColor::fromRgba(kColors[k % std::size(kColors)]);
}

QPointF WorldPainter::vaneCentre(const ViewTransform& view, int index, double lineScale)
{
    const QRectF box = view.shownBox();
    const double r = vaneRadius(lineScale);
    // Far enough apart that the labels, which start at a vane's left edge,
    // do not run into the next vane's ("smoothed  -267 px/s²" is about
    // 135 px at 12 px).
    const double x = box.left() + r + 14.0 * lineScale + index * (2.0 * r + 100.0 * lineScale);
    // Above the box when the space over it (the widget starts at y = 0)
    // holds a vane and its label, as in a small box in the normal layout,
    // so the vanes cover no ball; otherwise inside its top-left corner.
    const double label = 18.0 * lineScale, gap = 6.0 * lineScale;
    if (box.top() >= 2.0 * r + label + 2.0 * gap)
        return {x, box.top() - gap - label - r};
    return {x, box.top() + r + 14.0 * lineScale};
}

QStringList WorldPainter::readoutText(const sim::World& world, int selected, const sim::Matrix2X* accelerations,
                                      ReadoutShape shape)
{
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    if (n == 0)
        return {};
    const int i = selected >= 0 && selected < n ? selected : 0;
    const sim::Vec2 a = accelerations ? sim::Vec2(accelerations->col(i)) : sim::Vec2(0.0, 0.0);
    return readoutText(i, balls.position.col(i), balls.velocity.col(i), a, world.time(), shape);
}

QStringList WorldPainter::readoutText(const sim::World& world, int selected, const sim::Matrix2X* accelerations,
                                      bool wide)
{
    return readoutText(world, selected, accelerations, wide ? ReadoutShape::Wide : ReadoutShape::Panel);
}

QStringList WorldPainter::readoutText(int i, const sim::Vec2& x, const sim::Vec2& v, const sim::Vec2& a, double t,
                                      ReadoutShape shape)
{
    // Positions and speeds with one decimal, from 10⁵ on with a power of
    // ten (a stiff spring's −1.5 × 10⁶ px/s², never −1e+06); in SI
    // (ui/drawing/display_units.h) with the decimals of a tenth of a px
    // (three at 100 px = 1 m), so the columns keep their width.
    const ShownUnit lu = shownUnit(QStringLiteral("px"), displayUnits());
    const ShownUnit vu = shownUnit(QStringLiteral("px/s"), displayUnits());
    const ShownUnit au = shownUnit(QStringLiteral("px/s²"), displayUnits());
    auto shown = [](const ShownUnit& u, double value) {
        if (u.px == 0 && u.mass == 0)
            return oneDecimal(value);
        const double v = u.toShown(value);
        if (!std::isfinite(v) || std::abs(v) >= 1e5)
            return humanNumber(v, 4);
        const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(0.1 * u.factor()) - 1e-9)), 0, 6);
        QString text = QString::number(v, 'f', decimals);
        if (text.toDouble() == 0.0)
            text = QString::number(0.0, 'f', decimals); // no "−0.000"
        text.replace(QLatin1Char('-'), QChar(0x2212));
        return text;
    };
    const QString L = lu.text, V = vu.text, A = au.text;
    // The words in the program's language; the columns are padded to the
    // longest of them, so "Geschwindigkeit" keeps the numbers in line.
    const QString ball = tr("ball %1").arg(i);
    const QString speed = tr("speed");
    if (shape == ReadoutShape::Wide) {
        // Two long lines, for a strip above the box: it costs the box less height.
        auto w = [&shown](const ShownUnit& u, double value) { return shown(u, value).rightJustified(8); };
        const QString time = QStringLiteral("t %1 s").arg(t, 0, 'f', 3);
        const qsizetype head = std::max<qsizetype>(12, std::max(ball.size(), time.size()) + 2);
        return {
            ball.leftJustified(head) +
                QStringLiteral("x %1  y %2 %3    vx %4  vy %5 %6")
                    .arg(w(lu, x.x()), w(lu, x.y()), L, w(vu, v.x()), w(vu, v.y()), V),
            time.leftJustified(head) +
                QStringLiteral("ax %1  ay %2 %3  %4 %5 %6").arg(w(au, a.x()), w(au, a.y()), A, speed, w(vu, v.norm()), V),
        };
    }
    if (shape == ReadoutShape::Short) {
        // x and y side by side.
        return {
            ball, // the stage's clock line above has the time
            QStringLiteral("x %1  y %2 %3").arg(shown(lu, x.x()), shown(lu, x.y()), L),
            QStringLiteral("v (%1, %2) %3").arg(shown(vu, v.x()), shown(vu, v.y()), V),
            QStringLiteral("a (%1, %2) %3").arg(shown(au, a.x()), shown(au, a.y()), A),
            QStringLiteral("%1 %2 %3").arg(speed, shown(vu, v.norm()), V),
        };
    }
    auto num = [&shown](const ShownUnit& u, double value) { return shown(u, value).rightJustified(9); };
    const QString words[] = {tr("position"), tr("velocity"), tr("accel."), speed};
    qsizetype width = 8;
    for (const QString& word : words)
        width = std::max(width, word.size());
    auto label = [width](const QString& word) { return word.leftJustified(width + 1); };
    return {
        ball.leftJustified(width + 9) + u'x' + QString(8, u' ') + u'y',
        label(words[0]) + QStringLiteral("%1%2  %3").arg(num(lu, x.x()), num(lu, x.y()), L),
        label(words[1]) + QStringLiteral("%1%2  %3").arg(num(vu, v.x()), num(vu, v.y()), V),
        label(words[2]) + QStringLiteral("%1%2  %3").arg(num(au, a.x()), num(au, a.y()), A),
        label(words[3]) + QStringLiteral("%1 %2   t = %3 s").arg(num(vu, v.norm()), V).arg(t, 0, 'f', 3),
    };
}

QStringList WorldPainter::totalsText(const sim::World& world, bool wide)
{
    return totalsText(world.energy(), world.momentum(), wide, momentumScale(world));
}

double WorldPainter::momentumScale(const sim::World& world)
{
    const sim::BallState& balls = world.balls();
    double sum = 0.0;
    for (int i = 0; i < balls.size(); ++i)
        sum += balls.mass[i] * balls.velocity.col(i).norm();
    return sum;
}

namespace {

// The energies with four digits counted from the largest of kinetic and
// potential (a total that is their difference shows its rounding as 0),
// the momentum from the sum of the balls' own momenta (a total of balls
// moving apart reads 0, not −1.164 × 10⁻¹⁰).
struct TotalsNumbers {
    QString kinetic, potential, total, px, py;
};

TotalsNumbers totalsNumbers(const sim::Energy& pixelEnergy, const sim::Vec2& pixelMomentum, double momentumScale)
{
    // In the view's units (SI: J and kg·m/s).
    const ShownUnit eu = shownUnit(WorldPainter::kEnergyUnit, displayUnits());
    const ShownUnit pu = shownUnit(WorldPainter::kMomentumUnit, displayUnits());
    sim::Energy e = pixelEnergy;
    e.kinetic = eu.toShown(e.kinetic);
    e.potential = eu.toShown(e.potential);
    const sim::Vec2 p(pu.toShown(pixelMomentum.x()), pu.toShown(pixelMomentum.y()));
    momentumScale = pu.toShown(momentumScale);
    const double energyScale = std::max(std::abs(e.kinetic), std::abs(e.potential));
    const double pScale = std::max(momentumScale, p.norm());
    return {rounded(e.kinetic, energyScale), rounded(e.potential, energyScale), rounded(e.total(), energyScale),
            rounded(p.x(), pScale), rounded(p.y(), pScale)};
}

} // namespace

QStringList WorldPainter::totalsText(const sim::Energy& e, const sim::Vec2& m, bool wide, double momentumScale)
{
    const TotalsNumbers n = totalsNumbers(e, m, momentumScale);
    const QString kinetic = tr("kinetic"), potential = tr("potential"), total = tr("total");
    if (wide) {
        // Short lines beside the momenta inset, which is taller than three of them.
        return {
            tr("energy in %1: %2 %3").arg(unitText(kEnergyUnit), total, n.total),
            QStringLiteral("  %1 %2  %3 %4").arg(kinetic, n.kinetic, potential, n.potential),
            tr("momentum (%1, %2) %3").arg(n.px, n.py, unitText(kMomentumUnit)),
        };
    }
    const qsizetype width = std::max({kinetic.size(), potential.size(), total.size()}) + 1;
    return {
        tr("energy in %1").arg(unitText(kEnergyUnit)),
        QStringLiteral("  ") + kinetic.leftJustified(width) + n.kinetic,
        QStringLiteral("  ") + potential.leftJustified(width) + n.potential,
        QStringLiteral("  ") + total.leftJustified(width) + n.total,
        tr("momentum in %1").arg(unitText(kMomentumUnit)),
        QStringLiteral("  (%1, %2)").arg(n.px, n.py),
    };
}

QStringList WorldPainter::stageTotalsText(const sim::Energy& e, const sim::Vec2& p, bool column, double momentumScale)
{
    // Short lines under head lines that name the units: the bar sets them in
    // text columns, a group (a head line and the indented lines under it)
    // never split. In a column the momentum's x and y get a line each.
    const TotalsNumbers n = totalsNumbers(e, p, momentumScale);
    QStringList lines{tr("energy (%1)").arg(unitText(kEnergyUnit)), QStringLiteral("  %1 %2").arg(tr("kinetic"), n.kinetic),
                      QStringLiteral("  %1 %2").arg(tr("potential"), n.potential),
                      QStringLiteral("  %1 %2").arg(tr("total"), n.total), tr("momentum (%1)").arg(unitText(kMomentumUnit))};
    if (column)
        lines << QStringLiteral("  x %1").arg(n.px) << QStringLiteral("  y %1").arg(n.py);
    else
        lines << QStringLiteral("  (%1, %2)").arg(n.px, n.py);
    return lines;
}

} // namespace forcelab
