#pragma once
// Waiting for a window's layout to settle, as a condition and never as a
// time: a busy or slow machine only makes the wait longer.
//
// Qt lays widgets out in answer to posted events (layout requests, resizes,
// queued calls such as the stage bar's text fits), each of which may post
// more. A test that reads geometry after a fixed sleep reads whatever stage
// of that chain the machine reached: on a loaded two-core machine a 30 ms
// wait left a readout in a room 0 px wide. Here every posted event is
// delivered, round after round, until rounds in a row change no widget's
// geometry, font, visibility or text shape and no stage bar has a fit
// waiting.

#include "ui/stage/stage_bar.h"

#include <QCoreApplication>
#include <QLabel>
#include <QTest>
#include <QWidget>

namespace forcelab::test {

// What a reader of the window would see change: every widget's place and
// size, whether it shows, its font size and a label's text with every digit
// as 0 (a running clock changes numbers, not the layout).
inline QString layoutFingerprint(const QWidget* top)
{
    QString out;
    QList<const QWidget*> widgets{top};
    for (const QWidget* w : top->findChildren<QWidget*>())
        widgets << w;
    for (const QWidget* w : widgets) {
        const QRect g = w->geometry();
        out += QStringLiteral("%1 %2 %3 %4 %5 %6 %7;")
                   .arg(w->objectName())
                   .arg(g.x())
                   .arg(g.y())
                   .arg(g.width())
                   .arg(g.height())
                   .arg(w->isVisible() ? 1 : 0)
                   .arg(w->font().pointSizeF());
        if (const auto* label = qobject_cast<const QLabel*>(w)) {
            QString text = label->text();
            for (QChar& c : text)
                if (c.isDigit())
                    c = QLatin1Char('0');
            out += text;
        }
    }
    return out;
}

inline bool anyFitPending(const QWidget* top)
{
    for (const StageBar* bar : top->findChildren<StageBar*>())
        if (bar->isFitPending())
            return true;
    return false;
}

// True once `top` has settled (three rounds in a row without a change), false
// if it has not within `timeoutMs` (a layout that never settles is a bug).
inline bool waitForSettledLayout(QWidget* top, int timeoutMs = 20000)
{
    QString last;
    int quietRounds = 0;
    return QTest::qWaitFor(
        [&] {
            QCoreApplication::sendPostedEvents();
            const QString now = layoutFingerprint(top);
            quietRounds = (now == last && !anyFitPending(top)) ? quietRounds + 1 : 0;
            last = now;
            return quietRounds >= 3;
        },
        timeoutMs);
}

} // namespace forcelab::test
