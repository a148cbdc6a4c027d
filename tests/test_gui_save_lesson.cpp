// File > Save Scene as Lesson…, driven as a teacher would: lesson 29 with
// the ball restitution at 0.5, the dialog filled in by keyboard and mouse,
// the file reopened. It has the new title, the claims that no longer hold
// are gone and named in the status bar, and the ones kept hold.

#include "lessons/lesson_derive.h"
#include "lessons/sentence_check.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/controls/parameter_panel.h"
#include "ui/docks/lesson_text_view.h"
#include "ui/docks/lessons_dock.h"
#include "ui/window/main_window.h"
#include "ui/window/save_lesson_dialog.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>

using namespace forcelab;

class GuiSaveLessonTest : public QObject {
    Q_OBJECT
private slots:
    void savedSceneIsANewLessonWhoseClaimsHold();
    void escapeSavesNothing();
};

void GuiSaveLessonTest::savedSceneIsANewLessonWhoseClaimsHold()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("half-bouncy.json"));

    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("the-line-of-impact")));
    const Lesson old = window.lesson();
    window.controller()->pause();
    window.parameterPanel()->setShowAll(true);
    auto* restitution = window.parameterPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("ballRestitutionSpin"));
    QVERIFY(restitution);
    restitution->setValue(0.5);
    QCOMPARE(window.controller()->world().settings().collisions.restitution, 0.5);

    // The dialog is modal: fill it in once it is up.
    bool filled = false;
    QString refusal;
    QTimer poll;
    poll.setInterval(5);
    connect(&poll, &QTimer::timeout, this, [&] {
        auto* dialog = qobject_cast<SaveLessonDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        poll.stop();
        auto* title = dialog->findChild<QLineEdit*>(QStringLiteral("lessonTitleEdit"));
        auto* text = dialog->findChild<QPlainTextEdit*>(QStringLiteral("lessonTextEdit"));
        auto* keep = dialog->findChild<QCheckBox*>(QStringLiteral("keepTeacherNotesCheck"));
        auto* choose = dialog->findChild<QPushButton*>(QStringLiteral("chooseLessonFileButton"));
        auto* problem = dialog->findChild<QLabel*>(QStringLiteral("saveLessonProblemLabel"));
        QPushButton* save = dialog->findChild<QDialogButtonBox*>(QStringLiteral("saveLessonButtons"))
                                ->button(QDialogButtonBox::Save);
        if (!title || !text || !keep || !choose || !problem || !save) {
            dialog->reject();
            return;
        }
        const bool prefilled = title->text() == QStringLiteral("Based on The line of impact") &&
                               text->toPlainText() == lessons::creditSentence(old);
        title->selectAll();
        QTest::keyClicks(title, QStringLiteral("Half as bouncy"));
        // A sentence with a number nothing measures is refused, with the reason.
        text->setPlainText(QStringLiteral("The blue ball now leaves at 21 px/s."));
        refusal = problem->isVisible() && !save->isEnabled() ? problem->text() : QString();
        text->setPlainText(QStringLiteral("Here the balls give back less of their closing speed.\n\n"
                                          "Compare <this> & the lesson it is based on."));
        QTest::keyClick(keep, Qt::Key_Space);
        dialog->setFileChooser([&](QWidget*, const QString&) { return path; });
        QTest::mouseClick(choose, Qt::LeftButton);
        filled = prefilled && keep->isChecked() && save->isEnabled();
        QTest::keyClick(title, Qt::Key_Return); // Save is the default button
        if (dialog->isVisible())
            dialog->reject();
    });
    poll.start();
    window.findChild<QAction*>(QStringLiteral("saveAction"))->trigger();
    QVERIFY(filled);
    QVERIFY2(refusal.contains(QStringLiteral("“The blue ball now leaves at 21 px/s.”")), qPrintable(refusal));
    QTRY_VERIFY(QFileInfo::exists(path));

    // The status bar names what was dropped, by its words.
    const QString status = window.statusBar()->currentMessage();
    QVERIFY2(status.contains(QStringLiteral("“Half as bouncy”")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("“the readouts show about (25.2, 19.3) px/s for blue” (measured")),
             qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("Dropped questions: “%1”").arg(old.predict[0].ask)), qPrintable(status));

    QVERIFY(window.openLesson(path));
    const Lesson& saved = window.lesson();
    QCOMPARE(saved.title, QStringLiteral("Half as bouncy"));
    QCOMPARE(saved.id, QStringLiteral("half-bouncy"));
    QCOMPARE(saved.stage, lessons::kDerivedStage);
    QCOMPARE(saved.scene.settings.collisions.restitution, 0.5);
    QCOMPARE(saved.teacher.goal, old.teacher.goal); // asked for
    QVERIFY(saved.teacher.answers.isEmpty());
    QVERIFY(saved.claims.size() >= 2 && saved.claims.size() < old.claims.size());
    for (const sim::Claim& claim : saved.claims) {
        const sim::ClaimResult r = sim::checkClaim(saved.scene, claim);
        QVERIFY2(r.holds, qPrintable(QString::fromStdString(sim::describe(claim, r))));
    }
    const lessons::SentenceReport report = lessons::checkSentences(saved);
    QVERIFY2(report.problems.isEmpty(), qPrintable(report.problems.join(QLatin1Char('\n'))));
    // The lesson pane shows the new title and words, not stage 29.
    const QString shown = window.lessonsDock()->textBrowser()->toPlainText();
    QVERIFY2(shown.contains(QStringLiteral("Half as bouncy")) && !shown.contains(QStringLiteral("Stage 29")) &&
                 shown.contains(QStringLiteral("Compare <this> & the lesson it is based on.")),
             qPrintable(shown));
}

void GuiSaveLessonTest::escapeSavesNothing()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("never.json"));
    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("the-line-of-impact")));
    window.controller()->pause();
    bool seen = false;
    QTimer poll;
    poll.setInterval(5);
    connect(&poll, &QTimer::timeout, this, [&] {
        auto* dialog = qobject_cast<SaveLessonDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        poll.stop();
        auto* file = dialog->findChild<QLineEdit*>(QStringLiteral("lessonFileEdit"));
        if (file)
            file->setText(path);
        QTest::keyClick(dialog, Qt::Key_Escape);
        seen = !dialog->isVisible(); // Escape closed it
        if (dialog->isVisible())
            dialog->reject();
    });
    poll.start();
    window.findChild<QAction*>(QStringLiteral("saveAction"))->trigger();
    QVERIFY(seen);
    QVERIFY(!QFileInfo::exists(path));
    QCOMPARE(window.lesson().title, QStringLiteral("The line of impact"));
}

QTEST_MAIN(GuiSaveLessonTest)
#include "test_gui_save_lesson.moc"
