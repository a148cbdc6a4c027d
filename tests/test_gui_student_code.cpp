// Your Code: a student's own version of a file of the stage's JavaScript
// runs beside the reference from the same state; the first departure is
// found at its step with its size, errors name their file and line, an
// endless loop is stopped, the edits are kept per lesson and saved with it.

#include "gui_workbench.h"

#include "ui/canvas/canvas.h"
#include "ui/docks/student_code_dock.h"
#include "ui/script/script_pieces.h"

#include "lessons/lesson_loader.h"
#include "sim/world/world.h"

#include <QComboBox>
#include <QElapsedTimer>
#include <QFile>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>

#include <cmath>

using namespace forcelab;

namespace {

QPushButton* button(QWidget* dock, const QString& text)
{
    for (QPushButton* b : dock->findChildren<QPushButton*>())
        if (b->text() == text)
            return b;
    return nullptr;
}

// The student writes their version of `file`: the course's text with `from`
// replaced by `to`, typed into the real editor.
bool rewrite(StudentCodeDock* dock, const QString& file, const QString& from, const QString& to)
{
    dock->chooseFile(file);
    if (dock->currentFile() != file)
        return false;
    QString text = dock->editor()->toPlainText();
    if (!text.contains(from))
        return false;
    text.replace(from, to);
    dock->editor()->setPlainText(text);
    return dock->edits().value(file) == text;
}

const QString kSemiImplicit = QStringLiteral(
    "    b.vx = b.vx + h * acc[i].x;\n    b.vy = b.vy + h * acc[i].y;\n    b.x = b.x + h * b.vx;\n    b.y = b.y + h * b.vy;");
// The course's most common first bug: the position moved with the old velocity.
const QString kUpdateOrderBug = QStringLiteral(
    "    b.x = b.x + h * b.vx;\n    b.y = b.y + h * b.vy;\n    b.vx = b.vx + h * acc[i].x;\n    b.vy = b.vy + h * acc[i].y;");

} // namespace

class GuiStudentCodeTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    // Each test starts with no remembered code (the dock keeps it between sessions).
    void init() { QSettings().remove(QStringLiteral("studentCode")); }
    void theCoursesOwnCodeAgreesEvenAfterASeek();
    void anUpdateOrderBugDepartsAtStepOne();
    void anEndlessLoopIsStoppedAndSaid();
    void aSyntaxErrorMarksItsLine();
    void editsAreKeptPerLessonAndSavedWithIt();
    void aBadStudentCodeFieldIsOneLine();
    void theLessonsPanesComeBackAfterStop();
};

// Unchanged, the course's code is the engine's: lesson 10 (random
// accelerations, drawn from the seeded generator) agrees for 120 steps to 0 px;
// a step back restarts it from the recorded step and it agrees again.
void GuiStudentCodeTest::theCoursesOwnCodeAgreesEvenAfterASeek()
{
    test::Workbench w(QStringLiteral("random-acceleration"));
    QVERIFY(w.ready());
    StudentCodeDock* dock = w.window.studentCodeDock();
    Canvas* canvas = w.window.findChild<Canvas*>();
    QVERIFY(canvas);
    const QImage before = canvas->grab().toImage();
    QPushButton* run = button(dock, QStringLiteral("Run beside the reference"));
    QVERIFY(run);
    QTest::mouseClick(run, Qt::LeftButton);
    const StudentRun* student = w.controller()->studentRun();
    QVERIFY(student);
    QVERIFY2(!student->error(), qPrintable(student->error() ? student->error()->text() : QString()));
    QVERIFY(w.controller()->runToStep(120));
    QCOMPARE(student->steps(), 120);
    QVERIFY(!student->departure());
    QCOMPARE(student->separation(), 0.0);
    QVERIFY2(dock->statusText().contains(QStringLiteral("all 120 steps")), qPrintable(dock->statusText()));
    // Two panes now: the reference and the student's, each with its energy.
    const QStringList labels = canvas->paneLabels();
    QCOMPARE(labels.size(), 2);
    QVERIFY2(labels[0].startsWith(QStringLiteral("reference")) && labels[0].contains(QStringLiteral("energy")),
             qPrintable(labels[0]));
    QVERIFY2(labels[1].contains(QStringLiteral("agrees for 120 steps")), qPrintable(labels[1]));
    QTRY_VERIFY(canvas->grab().toImage() != before);

    // Back to step 60: the student's run starts again there, with the
    // generators 60 steps into their streams, and still agrees.
    QVERIFY(w.controller()->seekStep(60));
    QCOMPARE(student, w.controller()->studentRun());
    QCOMPARE(student->steps(), 0);
    QVERIFY(w.controller()->runToStep(150));
    QCOMPARE(student->steps(), 90);
    QVERIFY(!student->departure());
    QCOMPARE(student->separation(), 0.0);

    QTest::mouseClick(button(dock, QStringLiteral("Stop")), Qt::LeftButton);
    QVERIFY(!w.controller()->studentRun());
    QVERIFY(canvas->paneLabels().isEmpty());
}

// Lesson 07: the student moves the ball before changing its velocity. Their
// run departs at step 1, ball 0, in y, and the value is the engine's own
// explicit Euler to 1e-12; the first sub-step's difference is h²·g.
void GuiStudentCodeTest::anUpdateOrderBugDepartsAtStepOne()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    StudentCodeDock* dock = w.window.studentCodeDock();
    QVERIFY(dock->files().contains(QStringLiteral("step_semi_implicit_euler.js")));
    QVERIFY(rewrite(dock, QStringLiteral("step_semi_implicit_euler.js"), kSemiImplicit, kUpdateOrderBug));
    dock->run();
    QVERIFY(w.controller()->runToStep(30));
    const StudentRun* student = w.controller()->studentRun();
    QVERIFY(student && !student->error());
    QVERIFY(student->departure());
    const ScriptDeparture d = *student->departure();
    QCOMPARE(d.step, 1);
    QCOMPARE(d.ball, 0);
    QCOMPARE(d.field, QStringLiteral("y"));

    sim::Scene euler = w.controller()->scene();
    euler.settings.time.integrator = sim::IntegratorKind::Euler;
    sim::World reference(w.controller()->scene()), explicitEuler(euler);
    reference.step();
    explicitEuler.step();
    QCOMPARE(d.reference, reference.balls().position(1, 0));
    QVERIFY2(std::abs(d.student - explicitEuler.balls().position(1, 0)) <= 1e-12 * std::abs(d.student),
             qPrintable(QStringLiteral("%1 against Euler's %2").arg(d.student, 0, 'g', 17)
                            .arg(explicitEuler.balls().position(1, 0), 0, 'g', 17)));
    const sim::WorldSettings& s = w.controller()->world().settings();
    const double h = s.time.dt / s.time.substeps;
    if (s.time.substeps == 1)
        QVERIFY2(std::abs(d.size() - h * h * s.gravity.g.y()) <= 1e-9 * d.size(), qPrintable(QString::number(d.size(), 'g', 17)));
    QVERIFY2(dock->statusText().contains(QStringLiteral("Departs at step 1")) &&
                 dock->statusText().contains(QStringLiteral("ball 0")),
             qPrintable(dock->statusText()));
    Canvas* canvas = w.window.findChild<Canvas*>();
    QVERIFY2(canvas->paneLabels().value(1).contains(QStringLiteral("departs at step 1")),
             qPrintable(canvas->paneLabels().value(1)));
}

// `while (true) {}` in the gravity force: stopped after 1 s, said in the
// status line and over the pane; the reference runs on.
void GuiStudentCodeTest::anEndlessLoopIsStoppedAndSaid()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    StudentCodeDock* dock = w.window.studentCodeDock();
    const QString source = scriptPieceSource(QStringLiteral("gravity.js"));
    const QString body = QStringLiteral("function gravity(world, state, acc) {\n");
    QVERIFY2(source.contains(body), qPrintable(source));
    QVERIFY(rewrite(dock, QStringLiteral("gravity.js"), body, body + QStringLiteral("  while (true) {}\n")));
    dock->run();
    QElapsedTimer clock;
    clock.start();
    w.controller()->stepOnce();
    const qint64 ms = clock.elapsed();
    const StudentRun* student = w.controller()->studentRun();
    QVERIFY(student && student->error());
    QVERIFY2(student->error()->text().contains(QStringLiteral("stopped after 1 s")), qPrintable(student->error()->text()));
    QVERIFY2(ms < 20000, qPrintable(QString::number(ms)));
    QVERIFY2(dock->statusText().contains(QStringLiteral("Your code stopped")), qPrintable(dock->statusText()));
    QVERIFY(w.controller()->runToStep(5)); // the reference is not held up
    QCOMPARE(w.controller()->world().stepCount(), 5);
}

// A syntax error: the status names the file and line, and that line of the
// editor is marked and holds the cursor.
void GuiStudentCodeTest::aSyntaxErrorMarksItsLine()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    StudentCodeDock* dock = w.window.studentCodeDock();
    dock->chooseFile(QStringLiteral("gravity.js"));
    const QStringList lines = dock->editor()->toPlainText().split(QLatin1Char('\n'));
    int line = 0; // 1-based, the line the student breaks
    for (int i = 0; i < lines.size() && line == 0; ++i)
        if (lines[i].contains(QStringLiteral("acc[i].y")))
            line = i + 1;
    QVERIFY(line > 0);
    QVERIFY(rewrite(dock, QStringLiteral("gravity.js"), lines[line - 1], lines[line - 1] + QStringLiteral(" +* ;")));
    dock->run();
    const StudentRun* student = w.controller()->studentRun();
    QVERIFY(student && student->error());
    QCOMPARE(student->error()->file, QStringLiteral("gravity.js"));
    QCOMPARE(student->error()->line, line);
    QVERIFY2(dock->statusText().contains(QStringLiteral("gravity.js:%1").arg(line)), qPrintable(dock->statusText()));
    QCOMPARE(dock->editor()->textCursor().blockNumber(), line - 1);
    // The column, where the engine gives one (a syntax error): the cursor sits on the '*'.
    QCOMPARE(student->error()->column, lines[line - 1].size() + 3);
    QCOMPARE(dock->editor()->textCursor().positionInBlock(), student->error()->column - 1);
    QCOMPARE(dock->editor()->extraSelections().size(), 1);
    QCOMPARE(dock->editor()->extraSelections().front().cursor.blockNumber(), line - 1);
}

// Edits follow the lesson: another lesson opens with its own (none here),
// coming back brings them back; a saved lesson carries them, and opening the
// file gives them to the editor again.
void GuiStudentCodeTest::editsAreKeptPerLessonAndSavedWithIt()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    StudentCodeDock* dock = w.window.studentCodeDock();
    QVERIFY(rewrite(dock, QStringLiteral("step_semi_implicit_euler.js"), kSemiImplicit, kUpdateOrderBug));
    const ScriptEdits mine = dock->edits();
    QCOMPARE(mine.size(), 1);
    QVERIFY(w.window.openLesson(QStringLiteral("losing-energy")));
    QVERIFY(dock->edits().isEmpty());
    QVERIFY(w.window.openLesson(QStringLiteral("gravity")));
    QCOMPARE(dock->edits(), mine);
    QVERIFY(dock->editor()->toPlainText().contains(kUpdateOrderBug));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mine.json"));
    QVERIFY(w.window.saveLessonTo(path));
    const LoadResult loaded = LessonLoader::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errors().join(QLatin1Char('\n'))));
    QCOMPARE(loaded.lesson->studentCode, mine);

    QVERIFY(w.window.openLesson(QStringLiteral("losing-energy")));
    QVERIFY(w.window.openLesson(path));
    QCOMPARE(dock->edits(), mine);
}

// A shared lesson's "student_code" is checked like every field: a name that
// is not a course file name is one line naming the file and the field.
void GuiStudentCodeTest::aBadStudentCodeFieldIsOneLine()
{
    QTemporaryDir dir;
    QFile in(QStringLiteral(":/lessons/07-gravity.json"));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    const int brace = text.lastIndexOf('}');
    text.insert(brace, ",\n  \"student_code\": {\"../../etc/passwd\": \"x\"}\n");
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    const LoadResult loaded = LessonLoader::load(path);
    QVERIFY(!loaded.ok());
    QCOMPARE(loaded.errors().size(), 1);
    QVERIFY2(loaded.errors().front().contains(QStringLiteral("bad.json")) &&
                 loaded.errors().front().contains(QStringLiteral("student_code.../../etc/passwd")),
             qPrintable(loaded.errors().front()));
}

// Lesson 09 compares wall rules in three panes: the student's run takes
// their place and Stop gives them back, with their labels.
void GuiStudentCodeTest::theLessonsPanesComeBackAfterStop()
{
    test::Workbench w(QStringLiteral("bounce-at-the-right-moment"));
    QVERIFY(w.ready());
    std::vector<QString> before;
    for (const SimulationController::Pane& pane : w.controller()->comparePanes())
        before.push_back(pane.label);
    QVERIFY(before.size() >= 2);
    w.window.studentCodeDock()->run();
    QCOMPARE(w.controller()->comparePanes().size(), std::size_t{1});
    w.window.studentCodeDock()->stop();
    std::vector<QString> after;
    for (const SimulationController::Pane& pane : w.controller()->comparePanes())
        after.push_back(pane.label);
    QCOMPARE(after, before);
    QVERIFY(!w.controller()->studentRun());
}

QTEST_MAIN(GuiStudentCodeTest)
#include "test_gui_student_code.moc"
