// The Code panel: the marked regions of sim/ parse, match the source files
// line for line, and the panel shows and highlights what the settings run.

#include "ui/docks/code_dock.h"
#include "ui/docks/code_snippets.h"
#include "ui/canvas/simulation_controller.h"

#include "lessons/lesson_loader.h"
#include "sim/world/scene.h"
#include "ui/script/script_pieces.h"

#include <QFile>
#include <QTest>
#include <QTextEdit>
#include <QToolButton>

using namespace forcelab;

class GuiCodeTest : public QObject {
    Q_OBJECT
private slots:
    void regionsParseAndMatchTheSources();
    void markersThatDoNotParseAreReported();
    void panelFollowsTheSwitches();
    void switchShowsTheLessonsJavaScript();
};

// Every compiled-in region: no marker problem, a valid condition, and each
// shown line is that line of the file in sim/ (so the text cannot drift
// from what runs).
void GuiCodeTest::regionsParseAndMatchTheSources()
{
    const QList<CodeRegion>& regions = builtInCodeRegions();
    QVERIFY2(regions.size() >= 10, qPrintable(QString::number(regions.size())));
    QStringList names;
    for (const CodeRegion& r : regions) {
        QVERIFY2(!names.contains(r.name), qPrintable(r.name));
        names << r.name;
        QVERIFY2(r.test.key.isEmpty() || r.test.valid(), qPrintable(r.name));
        QVERIFY2(!r.lines.isEmpty(), qPrintable(r.name));
        QFile f(QStringLiteral(FORCELAB_SOURCE_DIR "/sim/") + r.file);
        QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(r.file));
        const QStringList source = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
        for (const CodeLine& l : r.lines) {
            QVERIFY2(source.value(l.number - 1).startsWith(l.text), qPrintable(QStringLiteral("%1:%2").arg(r.file).arg(l.number)));
            QVERIFY(l.test.key.isEmpty() || l.test.valid());
        }
    }
    for (const char* expected : {"step.euler", "step.semi-implicit-euler", "gravity", "drag", "spring", "walls.test",
                                 "response.axis-2d", "response.impulse-2d"})
        QVERIFY2(names.contains(QLatin1String(expected)), expected);
}

void GuiCodeTest::markersThatDoNotParseAreReported()
{
    QStringList problems;
    parseCodeRegions(QStringLiteral("// [code a if time.integrator=rk5: A]\nx\n// [code b: B]\ny\n"), QStringLiteral("f.cpp"),
                     &problems);
    QCOMPARE(problems.size(), 3);
    QVERIFY2(problems[0].startsWith(QStringLiteral("f.cpp:1: time.integrator=rk5 is not a parameter")), qPrintable(problems[0]));
    QVERIFY2(problems[1].startsWith(QStringLiteral("f.cpp:3: a region opens inside region a")), qPrintable(problems[1]));
    QVERIFY2(problems[2].startsWith(QStringLiteral("f.cpp:3: region b is never closed")), qPrintable(problems[2]));
}

// A lesson with the integrator and centre_only controls: both Euler steps are
// shown and the one that runs follows the setting; the radius line is
// highlighted exactly while centre_only is on.
void GuiCodeTest::panelFollowsTheSwitches()
{
    sim::Scene scene = sim::openScene({sim::ballAt(100, 100, 50, 0)});
    scene.settings.walls = sim::WallSettings{};
    scene.settings.gravity.enabled = true;
    SimulationController controller;
    QVERIFY(!controller.setScene(scene));
    CodeDock dock(&controller);
    dock.setLessonControls({QStringLiteral("integrator"), QStringLiteral("centre_only")});

    QVERIFY(dock.shownRegions().contains(QStringLiteral("step.euler")));
    QVERIFY(dock.shownRegions().contains(QStringLiteral("gravity")));
    QVERIFY(!dock.shownRegions().contains(QStringLiteral("spring"))); // off and not a control
    QVERIFY(dock.runningRegions().contains(QStringLiteral("step.semi-implicit-euler")));
    QVERIFY(!dock.runningRegions().contains(QStringLiteral("step.euler")));
    QVERIFY(dock.highlightedLines(QStringLiteral("walls.test")).isEmpty());

    sim::WorldSettings s = controller.world().settings();
    s.time.integrator = sim::IntegratorKind::Euler;
    s.walls.centreOnly = true;
    QVERIFY(controller.setSettings(s));
    QVERIFY(dock.runningRegions().contains(QStringLiteral("step.euler")));
    QVERIFY(!dock.runningRegions().contains(QStringLiteral("step.semi-implicit-euler")));
    QCOMPARE(dock.highlightedLines(QStringLiteral("walls.test")).size(), 1);
    auto* view = dock.findChild<QWidget*>(QStringLiteral("codeView"));
    QVERIFY(view);
}

// The C++ | JavaScript switch: a click shows the lesson's JavaScript, the
// pieces its settings run (its update step, its forces, its walls), whole and
// in a font readable at 1024×768; a click back shows the C++ again, and a
// change of settings changes the pieces.
void GuiCodeTest::switchShowsTheLessonsJavaScript()
{
    const LoadResult loaded = LessonLoader::load(QStringLiteral("07-gravity"));
    QVERIFY(loaded.ok());
    SimulationController controller;
    QVERIFY(!controller.setScene(loaded.lesson->scene));
    CodeDock dock(&controller);
    dock.resize(400, 600);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    auto* js = dock.findChild<QToolButton*>(QStringLiteral("codeJsButton"));
    auto* cpp = dock.findChild<QToolButton*>(QStringLiteral("codeCppButton"));
    QVERIFY(js && cpp);
    QVERIFY(dock.shownText().contains(QStringLiteral("sim/integrators/integrators.cpp")));
    QVERIFY(!dock.shownText().contains(QStringLiteral("function move(")));

    QTest::mouseClick(js, Qt::LeftButton);
    QTRY_VERIFY(dock.language() == CodeDock::Language::JavaScript);
    const QString text = dock.shownText();
    QCOMPARE(dock.shownPieces(), scriptPiecesFor(controller.world().settings()).files);
    for (const QString& piece : dock.shownPieces())
        for (const QString& line : scriptPieceSource(piece).split(QLatin1Char('\n')))
            QVERIFY2(text.contains(line), qPrintable(piece + QStringLiteral(": ") + line));
    QVERIFY(text.contains(QStringLiteral("function move(world, balls, h, t)"))); // semi-implicit Euler
    QVERIFY(text.contains(QStringLiteral("b.vy = b.vy + h * acc[i].y;")));
    QVERIFY(text.contains(QStringLiteral("function gravity(world, state, acc)")));
    QVERIFY(text.contains(QStringLiteral("function bounceOnWalls(world, balls, h)")));
    QVERIFY(!text.contains(QStringLiteral("function drag(")));
    auto* view = dock.findChild<QWidget*>(QStringLiteral("codeView"));
    QVERIFY(view);
    QVERIFY2(qobject_cast<QTextEdit*>(view)->document()->defaultFont().pointSizeF() >= 12.0, "too small for a room");

    sim::WorldSettings s = controller.world().settings();
    s.drag.enabled = true;
    QVERIFY(controller.setSettings(s));
    QTRY_VERIFY(dock.shownText().contains(QStringLiteral("function drag(world, state, acc)")));

    QTest::mouseClick(cpp, Qt::LeftButton);
    QTRY_VERIFY(dock.language() == CodeDock::Language::Cpp);
    QVERIFY(!dock.shownText().contains(QStringLiteral("function move(")));
    QVERIFY(dock.shownText().contains(QStringLiteral("sim/forces/force_models.cpp")));
}

QTEST_MAIN(GuiCodeTest)
#include "test_gui_code.moc"
