// The stage view for a projector: at 1024×768, 1280×720 and 1920×1080 the
// simulation fills at least 80% of the window, with the lesson's title and
// challenge as a caption and large transport buttons beside or under it;
// Escape leaves it and gives back the docks. In the normal layout the
// readouts never cover the box, and opening a dock does not shrink it.

#include "ui/canvas.h"
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "ui/world_painter.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QStandardPaths>
#include <QTest>
#include <QToolButton>

using namespace forcelab;

class GuiStageTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void stageFillsTheScreen_data();
    void stageFillsTheScreen();
    void quittingFromTheStageKeepsTheNormalLayout();
};

void GuiStageTest::stageFillsTheScreen_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1024x768") << QSize(1024, 768);
    QTest::newRow("1280x720") << QSize(1280, 720);
    QTest::newRow("1920x1080") << QSize(1920, 1080);
}

void GuiStageTest::stageFillsTheScreen()
{
    QFETCH(QSize, size);
    MainWindow window(QStringLiteral("gravity"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QAction* stage = window.findChild<QAction*>(QStringLiteral("presentationAction"));
    QVERIFY(stage);
    stage->setChecked(true);
    window.showNormal(); // the test sizes the window itself, whatever the test screen is
    window.setGeometry(QRect(QPoint(0, 0), size));
    QTRY_COMPARE(window.size(), size);
    QTest::qWait(50);

    const double windowArea = double(size.width()) * size.height();
    Canvas* canvas = window.canvas();
    const QRectF box = canvas->viewTransform().boxRect();
    const double boxShare = box.width() * box.height() / windowArea;
    qInfo("%dx%d: the box takes %.1f%% of the window (%.0f x %.0f px)", size.width(), size.height(), 100 * boxShare,
          box.width(), box.height());
    QVERIFY2(boxShare >= 0.80, qPrintable(QString::number(boxShare)));
    QVERIFY(!window.menuBar()->isVisible());
    for (QDockWidget* dock : window.findChildren<QDockWidget*>())
        QVERIFY2(!dock->isVisible(), qPrintable(dock->objectName()));
    // The caption and the big buttons.
    auto* title = window.findChild<QLabel*>(QStringLiteral("stageTitle"));
    QVERIFY(title && title->isVisible());
    QCOMPARE(title->text(), window.lesson().title);
    const auto buttons = window.findChild<QWidget*>(QStringLiteral("stageBar"))->findChildren<QToolButton*>();
    QCOMPARE(buttons.size(), 5);
    for (QToolButton* b : buttons)
        QVERIFY(b->isVisible() && b->height() >= 56);
    // Run from the stage bar.
    QVERIFY(!window.controller()->isPlaying());
    buttons.first()->click();
    QVERIFY(window.controller()->isPlaying());
    window.controller()->pause();

    // Escape leaves: the docks and menus are back.
    QTest::keyClick(&window, Qt::Key_Escape);
    QVERIFY(!stage->isChecked());
    QVERIFY(window.menuBar()->isVisible());
    QVERIFY(!window.findChild<QWidget*>(QStringLiteral("stageBar"))->isVisible());
}

// Quitting in the stage view: the next start has its docks, menus and toolbars.
void GuiStageTest::quittingFromTheStageKeepsTheNormalLayout()
{
    {
        MainWindow window(QStringLiteral("gravity"));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QAction*>(QStringLiteral("presentationAction"))->setChecked(true);
        window.close(); // saves the settings
    }
    MainWindow again(QStringLiteral("gravity"));
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QVERIFY(again.menuBar()->isVisible());
    QVERIFY(again.findChild<QDockWidget*>(QStringLiteral("parametersDock"))->isVisible());
    QVERIFY(again.findChild<QDockWidget*>(QStringLiteral("lessonsDock"))->isVisible());
}

QTEST_MAIN(GuiStageTest)
#include "test_gui_stage.moc"
