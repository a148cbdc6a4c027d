// View → Language switches the whole window live: a new window in the new
// language replaces the old one with the same lesson, the same world (balls,
// clock) and the same selection, and the choice is remembered.

#include "gui_settle.h"

#include "ui/canvas/canvas.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/controls/number_control.h"
#include "ui/docks/lesson_text_view.h"
#include "ui/window/language.h"
#include "ui/window/main_window.h"
#include "ui/window/window_host.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <cmath>

using namespace forcelab;

namespace {

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

    // The user picks Deutsch in View → Language.
    QAction* deutsch = english->findChild<QAction*>(QStringLiteral("language_de"));
    QVERIFY(deutsch);
    QCOMPARE(deutsch->text(), QStringLiteral("Deutsch"));
    deutsch->trigger();
    QTRY_VERIFY(host.window() != english);
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

    // The lesson's text is English, and the panel says so in German.
    const QString notice = QCoreApplication::translate(
        "forcelab::LessonsDock", "This lesson is not written in your language yet: its text is shown in English.");
    auto* text = german->findChild<LessonTextView*>();
    QVERIFY(text);
    QVERIFY2(text->toPlainText().contains(notice), qPrintable(text->toPlainText().left(300)));

    // And it runs on from there.
    QVERIFY(german->controller()->runToStep(german->controller()->world().stepCount() + 10));

    german->findChild<QAction*>(QStringLiteral("language_en"))->trigger();
    QTRY_VERIFY(host.window() != german);
    QVERIFY(menuTitles(host.window()).contains(QStringLiteral("&View")));
    QVERIFY(!host.window()->findChild<LessonTextView*>()->toPlainText().contains(QStringLiteral("not written in your language")));
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
