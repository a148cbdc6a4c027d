#include "overlay_actions.h"

#include "canvas.h"
#include "world_painter.h"

#include <QAction>
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
    add(QStringLiteral("showAcceleration"), tr("&Force arrows (net force per mass, a = F/m)"), &Overlays::acceleration);
    add(QStringLiteral("showTrails"), tr("&Paths"), &Overlays::trails);
    add(QStringLiteral("showReadout"), tr("&Readout of the selected ball"), &Overlays::readout);
    add(QStringLiteral("showTotals"), tr("&Totals: energy and momentum"), &Overlays::totals);
    add(QStringLiteral("showColliding"), tr("&Mark touching balls"), &Overlays::colliding);
    add(QStringLiteral("showGrid"), tr("&Grid"), &Overlays::grid);
    add(QStringLiteral("showMarkers"), tr("&Markers (centres, anchors, homes)"), &Overlays::markers);
    m_menu->addSeparator();
    m_autoArrows = m_menu->addAction(tr("Arrows of a readable &length"));
    m_autoArrows->setObjectName(QStringLiteral("autoArrows"));
    m_autoArrows->setCheckable(true);
    m_autoArrows->setChecked(true);
    m_autoArrows->setToolTip(tr("Scale the arrows so that a typical one is about 45 px long; off: the lesson's scale"));
    connect(m_autoArrows, &QAction::toggled, m_canvas, &Canvas::setAutoArrows);
    m_canvas->setAutoArrows(true);
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
