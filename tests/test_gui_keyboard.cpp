// A whole lesson with keys alone: open it (Alt+→ from the one before),
// answer the prediction, run and pause, change a slider, start and stop the
// stopwatch, reset. Every key goes to the widget that has the keyboard
// focus, as a keyboard user's keys do; no mouse, no direct calls.

#include "gui_workbench.h"

#include "ui/canvas/canvas.h"
#include "ui/docks/predict_dock.h"
#include "ui/docks/stopwatch_dock.h"
#include "ui/controls/parameter_panel.h"
#include "ui/controls/number_control.h"
#include "ui/controls/focus_ring.h"
#include "sim/world/parameters.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSlider>
#include <QStandardPaths>
#include <QTabBar>
#include <QTest>

using namespace forcelab;

namespace {

QWidget* focus()
{
    return QApplication::focusWidget();
}

void press(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QTest::keyClick(focus(), static_cast<Qt::Key>(key), modifiers);
}

// Every settable value of the world, to tell that one changed.
std::vector<double> settingValues(const sim::WorldSettings& s)
{
    std::vector<double> values;
    for (const sim::Parameter& p : sim::parameters())
        values.push_back(p.get(s));
    return values;
}

// The key the Tools menu gives `title` ("Predict", "Stopwatch").
QKeySequence toolKey(MainWindow& window, const QString& title)
{
    for (QAction* a : window.actions())
        if (a->text() == title && !a->shortcut().isEmpty())
            return a->shortcut();
    return {};
}

// Tab until `found` says the focus is where it should be; false after a whole round.
template <typename Found>
bool tabTo(Found found)
{
    QStringList seen;
    for (int k = 0; k < 400; ++k) {
        if (found(focus()))
            return true;
        if (k < 60 && focus())
            seen << QStringLiteral("%1(%2)").arg(QString::fromLatin1(focus()->metaObject()->className()), focus()->objectName());
        press(Qt::Key_Tab);
    }
    qInfo("Tab went through: %s", qPrintable(seen.join(QStringLiteral(" → "))));
    return false;
}

} // namespace

class GuiKeyboardTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void aWholeLessonWithKeysAlone();
};

void GuiKeyboardTest::aWholeLessonWithKeysAlone()
{
    test::Workbench w(QStringLiteral("attraction-and-the-slingshot")); // lesson 17
    QVERIFY(w.ready());
    QTRY_VERIFY(focus() != nullptr);

    // Open lesson 18 with Alt+→.
    press(Qt::Key_Right, Qt::AltModifier);
    QTRY_COMPARE(w.window.lesson().id, QStringLiteral("elastic-band"));
    QTRY_VERIFY(focus() != nullptr);

    // The Predict tool's key takes the keyboard into its answer; Enter locks it in and runs.
    const QKeySequence predictKey = toolKey(w.window, QStringLiteral("Predict"));
    QVERIFY(!predictKey.isEmpty());
    press(predictKey[0].key());
    auto* predict = w.window.findChild<PredictDock*>();
    QVERIFY(predict);
    QTRY_VERIFY(qobject_cast<QLineEdit*>(focus()) && predict->isAncestorOf(focus()));
    QTest::keyClicks(focus(), QStringLiteral("2"));
    press(Qt::Key_Return);
    QTRY_VERIFY(predict->predicted().has_value());

    // Escape takes the keyboard back to the canvas; Space pauses and runs.
    press(Qt::Key_Escape);
    QTRY_VERIFY(qobject_cast<Canvas*>(focus()));
    const bool wasPlaying = w.controller()->isPlaying();
    press(Qt::Key_Space);
    QTRY_VERIFY(w.controller()->isPlaying() != wasPlaying);
    if (!w.controller()->isPlaying()) {
        press(Qt::Key_Space);
        QTRY_VERIFY(w.controller()->isPlaying());
    }
    press(Qt::Key_Space);
    QTRY_VERIFY(!w.controller()->isPlaying());

    // Tab to a number of the Parameters panel (a row's slider and field are
    // one control; the field takes the keyboard) and step it with ↑.
    QVERIFY(w.window.parameterPanel()->isVisible());
    QVERIFY(tabTo([&](QWidget* f) {
        auto* spin = qobject_cast<NumberSpinBox*>(f);
        return spin && w.window.parameterPanel()->isAncestorOf(spin) && spin->value() < spin->maximum();
    }));
    // The focus ring is round it, in the plain theme and the projector theme.
    auto* ring = w.window.findChild<FocusRing*>();
    QVERIFY(ring);
    auto ringIsRound = [&] {
        const QRect target(focus()->mapTo(&w.window, QPoint(0, 0)), focus()->size());
        return ring->isVisible() && ring->target() == focus() && ring->geometry().contains(target) &&
               w.window.rect().contains(target) && // in sight: its panel came forward
               !focus()->visibleRegion().isEmpty() &&
               ring->geometry().adjusted(8, 8, -8, -8).width() < target.width();
    };
    QTRY_VERIFY(ringIsRound());
    const QImage plain = w.window.grab().toImage();
    auto* projector = w.window.findChild<QAction*>(QStringLiteral("themeAction"));
    QVERIFY(projector);
    projector->setChecked(true);
    QTRY_VERIFY(ringIsRound());
    projector->setChecked(false);
    QTRY_VERIFY(ringIsRound());
    ring->hide();
    QVERIFY(w.window.grab().toImage() != plain); // the ring is in the picture
    ring->show();

    const std::vector<double> before = settingValues(w.controller()->world().settings());
    press(Qt::Key_Up);
    QTRY_VERIFY(settingValues(w.controller()->world().settings()) != before);
    QVERIFY(!w.controller()->isPlaying()); // the slider took the key, not the simulation

    // The Stopwatch's key, then Space on its start button starts it; running, Space stops it.
    press(Qt::Key_Escape);
    const QKeySequence stopwatchKey = toolKey(w.window, QStringLiteral("Stopwatch"));
    QVERIFY(!stopwatchKey.isEmpty());
    press(stopwatchKey[0].key());
    auto* stopwatch = w.window.findChild<StopwatchDock*>();
    QVERIFY(stopwatch);
    QTRY_VERIFY(focus() && stopwatch->isAncestorOf(focus()));
    QVERIFY(tabTo([&](QWidget* f) {
        auto* b = qobject_cast<QPushButton*>(f);
        return b && stopwatch->isAncestorOf(b) && b->objectName() == QLatin1String("stopwatchStartStop");
    }));
    QCOMPARE(stopwatch->state(), StopwatchDock::State::Idle);
    press(Qt::Key_Space); // Space presses the focused button; it does not run the simulation
    QTRY_COMPARE(stopwatch->state(), StopwatchDock::State::Running);
    QVERIFY(!w.controller()->isPlaying());
    press(Qt::Key_Return); // Enter presses it too
    QTRY_COMPARE(stopwatch->state(), StopwatchDock::State::Stopped);

    // Enter ticks the check box that has the keyboard (Space would run the simulation there).
    QVERIFY(tabTo([&](QWidget* f) { return f && f->objectName() == QLatin1String("showAllCheck"); }));
    auto* showAll = qobject_cast<QCheckBox*>(focus());
    QVERIFY(showAll);
    const bool ticked = showAll->isChecked();
    press(Qt::Key_Return);
    QTRY_VERIFY(showAll->isChecked() != ticked);

    // R on the canvas resets the lesson: t = 0, its own settings.
    press(Qt::Key_Escape);
    QTRY_VERIFY(qobject_cast<Canvas*>(focus()));
    press(Qt::Key_R);
    QTRY_COMPARE(w.controller()->world().time(), 0.0);
}

QTEST_MAIN(GuiKeyboardTest)
#include "test_gui_keyboard.moc"
