#include "ui/controls/focus_ring.h"

#include <QApplication>
#include <QDockWidget>
#include <QTimer>
#include <QEvent>
#include <QPainter>

namespace forcelab {

FocusRing::FocusRing(QWidget* window)
    : QWidget(window)
{
    setObjectName(QStringLiteral("focusRing"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setFocusPolicy(Qt::NoFocus);
    hide();
    connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) { follow(now); });
}

void FocusRing::follow(QWidget* now)
{
    for (const QPointer<QWidget>& w : m_watched)
        if (w)
            w->removeEventFilter(this);
    m_watched.clear();
    m_target = nullptr;
    // Only controls of this window, and not the canvas.
    if (now && now->window() == window() && !now->inherits("forcelab::Canvas") && now != this) {
        m_target = now;
        for (QWidget* w = now; w && w != window(); w = w->parentWidget()) {
            w->installEventFilter(this);
            m_watched << w;
            // A panel stacked behind another keeps its place off the screen: bring it forward.
            if (auto* dock = qobject_cast<QDockWidget*>(w); dock && !dock->isFloating() && dock->visibleRegion().isEmpty())
                dock->raise();
        }
    }
    place();
    QTimer::singleShot(0, this, &FocusRing::place); // after the panels' layout settles
}

void FocusRing::place()
{
    if (!m_target || !m_target->isVisible()) {
        hide();
        return;
    }
    const int m = kWidth + 1;
    const QRect inWindow(m_target->mapTo(window(), QPoint(0, 0)), m_target->size());
    setGeometry(inWindow.adjusted(-m, -m, m, m));
    show();
    raise();
    update();
}

bool FocusRing::eventFilter(QObject* watched, QEvent* event)
{
    if (m_target && m_watched.contains(qobject_cast<QWidget*>(watched))) {
        switch (event->type()) {
        case QEvent::Move:
        case QEvent::Resize:
        case QEvent::Show:
        case QEvent::Hide:
            place();
            break;
        default:
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void FocusRing::paintEvent(QPaintEvent*)
{
    // Orange with a dark edge: seen on the light panels and on the dark stage.
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5);
    p.setPen(QPen(QColor(0x20, 0x20, 0x20), kWidth + 1.0));
    p.drawRoundedRect(r, 4, 4);
    p.setPen(QPen(QColor(0xff, 0x98, 0x00), kWidth - 0.5));
    p.drawRoundedRect(r, 4, 4);
}

} // namespace forcelab
