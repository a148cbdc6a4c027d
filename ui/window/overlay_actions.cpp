#include "ui/window/overlay_actions.h"

#include "ui/canvas/canvas.h"
#include "ui/drawing/world_painter.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QSignalBlocker>

namespace forcelab {

OverlayActions::OverlayActions(Canvas* canvas, QWidget* parent)
    : QObject(parent)
    , m_canvas(canvas)
{
    m_menu = new QMenu(tr("&Show"), parent);
    m_menu->setObjectName(QStringLiteral("showMenu"));
    add(QStringLiteral("showVelocity"), tr("&Velocity arrows"), &Overlays::velocity);
    add(QStringLiteral("showAcceleration"), tr("&Acceleration arrows (a = F/m)"), &Overlays::acceleration);
    add(QStringLiteral("showForces"), tr("&Force arrows (net force F = m a)"), &Overlays::forces);
    add(QStringLiteral("showForceSources"), tr("Forces &by source (one arrow per force)"), &Overlays::forceSources);
    add(QStringLiteral("showTrails"), tr("&Paths"), &Overlays::trails);
    add(QStringLiteral("showCentreOfMass"), tr("&Centre of mass and its path"), &Overlays::centreOfMass);
    add(QStringLiteral("showMomenta"), tr("M&omenta diagram (p = m v, tip to tail)"), &Overlays::momenta);
    add(QStringLiteral("showApexes"), tr("Tops of the flights, with their &heights"), &Overlays::apexes);
    add(QStringLiteral("showReadout"), tr("&Readout of the selected ball"), &Overlays::readout);
    add(QStringLiteral("showTotals"), tr("&Totals: energy and momentum"), &Overlays::totals);
    add(QStringLiteral("showColliding"), tr("&Mark touching balls"), &Overlays::colliding);
    add(QStringLiteral("showGrid"), tr("&Grid"), &Overlays::grid);
    add(QStringLiteral("showMarkers"), tr("&Markers (centres, anchors, homes)"), &Overlays::markers);
    m_menu->addSeparator();
    // How long the arrows are: auto keeps the median arrow about 45 px long
    // (readable at the back of a room); the others multiply the lesson's own
    // scales, so the arrows of two frames can be compared.
    QMenu* length = m_menu->addMenu(tr("Arrow &length"));
    length->setObjectName(QStringLiteral("arrowLengthMenu"));
    auto* group = new QActionGroup(this);
    m_autoArrows = length->addAction(tr("&Auto: readable (about 45 px)"));
    m_autoArrows->setObjectName(QStringLiteral("autoArrows"));
    m_autoArrows->setCheckable(true);
    m_autoArrows->setChecked(true);
    group->addAction(m_autoArrows);
    connect(m_autoArrows, &QAction::toggled, m_canvas, &Canvas::setAutoArrows);
    for (double factor : kArrowFactors) {
        const QString text = factor == 1.0 ? tr("The lesson's scale (×1)") : tr("×%1 the lesson's scale").arg(factor);
        QAction* a = length->addAction(text);
        a->setObjectName(QStringLiteral("arrowFactor%1").arg(factor));
        a->setCheckable(true);
        group->addAction(a);
        connect(a, &QAction::toggled, this, [this, factor](bool on) {
            if (on)
                m_canvas->setArrowFactor(factor);
        });
    }
    m_canvas->setAutoArrows(true);
    // Auto arrows keep one scale through a run, so slowing down shows; the
    // teacher can make them longer or shorter, or fix the scale again now.
    const auto runAction = [this, length](const char* name, const QString& text, auto slot) {
        QAction* a = length->addAction(text);
        a->setObjectName(QString::fromLatin1(name));
        connect(a, &QAction::triggered, m_canvas, slot);
    };
    length->addSeparator();
    runAction("arrowsLonger", tr("Arrow scale ×&2"), [this] { m_canvas->scaleRunArrows(2.0); });
    runAction("arrowsShorter", tr("Arrow scale ÷2"), [this] { m_canvas->scaleRunArrows(0.5); });
    runAction("arrowsFromNow", tr("Arrow scale &from now"), [this] { m_canvas->fixRunArrowsFromNow(); });
    // The actions show what is drawn, whoever changed it (a lesson, a panel).
    connect(m_canvas, &Canvas::overlaysChanged, this, &OverlayActions::sync);
}

void OverlayActions::add(const QString& name, const QString& text, bool Overlays::*member)
{
    QAction* a = m_menu->addAction(text);
    a->setObjectName(name);
    a->setCheckable(true);
    connect(a, &QAction::toggled, this, [this, member](bool on) {
        Overlays o = m_canvas->overlays();
        o.*member = on;
        m_canvas->setOverlays(o);
    });
    m_actions.append({a, member});
}

void OverlayActions::sync()
{
    const Overlays& o = m_canvas->overlays();
    for (const auto& [action, member] : m_actions) {
        const QSignalBlocker block(action);
        action->setChecked(o.*member);
    }
}

} // namespace forcelab
