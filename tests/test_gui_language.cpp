// View → Language switches the whole window live: a new window in the new
// language replaces the old one with the same lesson, the same world (balls,
// clock) and the same selection, and the choice is remembered.

#include "gui_settle.h"

#include "ui/canvas/canvas.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/controls/number_control.h"
#include "ui/docks/lesson_text_view.h"
#include "lessons/atomic_file.h"
#include "lessons/lesson_languages.h"
#include "lessons/lesson_loader.h"
#include "lessons/lesson_markup.h"
#include "lessons/sentence_check.h"
#include "ui/drawing/handbook.h"
#include "ui/window/language.h"
#include "ui/window/main_window.h"
#include "ui/window/window_host.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace forcelab;

namespace {

/// How long a language switch may take to rebuild the window, in ms.
constexpr int kRebuildMs = 60000;

QStringList menuTitles(MainWindow* window)
{
    QStringList titles;
    for (QAction* a : window->menuBar()->actions())
        titles << a->text();
    return titles;
}

} // namespace

class GuiLanguageTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }
    void cleanup() { applyLanguage(QStringLiteral("en")); }
    void switchingKeepsTheClassesWorkAndIsRemembered();
    void aDamagedSettingFallsBackToEnglishAndSaysSo();
};

void GuiLanguageTest::switchingKeepsTheClassesWorkAndIsRemembered()
{
    WindowHost host(QStringLiteral("gravity"));
    MainWindow* english = host.window();
    english->resize(1280, 720);
    english->show();
    QVERIFY(QTest::qWaitForWindowExposed(english));
    QVERIFY(menuTitles(english).contains(QStringLiteral("&View")));
    QVERIFY(english->controller()->runToStep(90));
    english->canvas()->setSelectedBall(2);
    const sim::BallState before = english->controller()->world().balls();
    const double time = english->controller()->world().time();

    QSignalSpy replaced(&host, &WindowHost::windowReplaced);
    // The user picks Deutsch in View → Language.
    QAction* deutsch = english->findChild<QAction*>(QStringLiteral("language_de"));
    QVERIFY(deutsch);
    QCOMPARE(deutsch->text(), QStringLiteral("Deutsch"));
    deutsch->trigger();
    // The new window is built in a queued call; on a busy machine that takes
    // a while (kRebuildMs), so wait for it rather than the default 5 s. The
    // host says when it has replaced the window: comparing pointers is not
    // enough, since the new window may be built where the old one was.
    QTRY_COMPARE_WITH_TIMEOUT(replaced.count(), 1, kRebuildMs);
    MainWindow* german = host.window();
    QVERIFY(QTest::qWaitForWindowExposed(german));
    QCOMPARE(currentLanguage(), QStringLiteral("de"));
    QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("de"));
    const QString view = QCoreApplication::translate("forcelab::MainWindow", "&View");
    QVERIFY2(menuTitles(german).contains(view) && !menuTitles(german).contains(QStringLiteral("&View")),
             qPrintable(menuTitles(german).join(QLatin1Char(' '))));
    // The class's work is all there: the lesson, the clock, every ball, the selection.
    QCOMPARE(german->lesson().id, QStringLiteral("gravity"));
    QCOMPARE(german->controller()->world().time(), time);
    const sim::BallState& after = german->controller()->world().balls();
    QCOMPARE(after.size(), before.size());
    QVERIFY(after.position == before.position && after.velocity == before.velocity);
    QCOMPARE(german->canvas()->selectedBall(), 2);
    QVERIFY(german->findChild<QAction*>(QStringLiteral("language_de"))->isChecked());

    // Number fields write and read numbers the German way: the time step
    // reads "0,01667" and typing "0,02" gives 0.02 s.
    bool sawComma = false;
    for (NumberSpinBox* box : german->findChildren<NumberSpinBox*>())
        if (box->isVisibleTo(german) && box->value() != std::round(box->value()) && std::isfinite(box->value())) {
            QVERIFY2(box->text().contains(QLatin1Char(',')) && !box->text().contains(QLatin1Char('.')),
                     qPrintable(box->text()));
            QCOMPARE(box->valueFromText(QStringLiteral("0,02")), 0.02);
            sawComma = true;
        }
    QVERIFY(sawComma);

    // The lesson speaks German too: the panel shows its German words, and
    // the claims the class checks quote them.
    const LoadResult loaded = LessonLoader::load(QStringLiteral("gravity"));
    QVERIFY(loaded.ok());
    const Lesson deLesson = lessons::shownIn(*loaded.lesson, QStringLiteral("de"));
    QCOMPARE(deLesson.language, QStringLiteral("de"));
    QCOMPARE(german->lesson().language, QStringLiteral("de"));
    QCOMPARE(german->lesson().title, deLesson.title);
    auto* text = german->findChild<LessonTextView*>();
    QVERIFY(text);
    const QString shownText = text->toPlainText();
    QVERIFY2(shownText.contains(lessons::markupToPlainText(deLesson.title)) &&
                 shownText.contains(lessons::splitSentences(deLesson.text).value(0)) &&
                 !shownText.contains(lessons::splitSentences(loaded.lesson->text).value(0)),
             qPrintable(shownText.left(300)));
    const QString notice = QCoreApplication::translate(
        "Language", "This lesson is not written in your language yet: its text is shown in %1.").arg(languageName("en"));
    QVERIFY(!shownText.contains(notice));
    QCOMPARE(german->lesson().claims.front().text, deLesson.claims.front().text);

    // A lesson file without German (a stranger's, say) is shown in its own
    // language, and the panel says so in German.
    QTemporaryDir dir;
    Lesson onlyEnglish = *loaded.lesson;
    onlyEnglish.languages.clear();
    const QString path = dir.filePath(QStringLiteral("only-english.json"));
    QVERIFY(lessons::writeFileAtomically(path, saveLesson(onlyEnglish), nullptr));
    QVERIFY(german->openLesson(path));
    QCOMPARE(german->lesson().language, QStringLiteral("en"));
    QVERIFY2(text->toPlainText().contains(notice) && notice.contains(QStringLiteral("Englisch")),
             qPrintable(text->toPlainText().left(300)));
    QVERIFY(german->openLesson(QStringLiteral("gravity")));
    QVERIFY(german->controller()->runToStep(90));

    // And it runs on from there.
    QVERIFY(german->controller()->runToStep(german->controller()->world().stepCount() + 10));

    german->findChild<QAction*>(QStringLiteral("language_en"))->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(replaced.count(), 2, kRebuildMs);
    QVERIFY(menuTitles(host.window()).contains(QStringLiteral("&View")));
    const QString back = host.window()->findChild<LessonTextView*>()->toPlainText();
    QVERIFY(!back.contains(QStringLiteral("not written in your language")));
    QVERIFY2(back.contains(lessons::splitSentences(loaded.lesson->text).value(0)), qPrintable(back.left(300)));
    QCOMPARE(host.window()->lesson().language, QStringLiteral("en"));
    QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("en"));
}

void GuiLanguageTest::aDamagedSettingFallsBackToEnglishAndSaysSo()
{
    QSettings().setValue(QStringLiteral("language"), QStringLiteral("klingon"));
    QString problem;
    QCOMPARE(rememberedLanguage(&problem), QStringLiteral("en"));
    QVERIFY2(problem.contains(QStringLiteral("language")) && problem.contains(QStringLiteral("klingon")), qPrintable(problem));
    QSettings().setValue(QStringLiteral("language"), QStringLiteral("de"));
    QCOMPARE(rememberedLanguage(), QStringLiteral("de"));
    WindowHost host(QStringLiteral("gravity"));
    QCOMPARE(currentLanguage(), QStringLiteral("de"));
    QSettings().remove(QStringLiteral("language"));
}

QTEST_MAIN(GuiLanguageTest)
#include "test_gui_language.moc"
