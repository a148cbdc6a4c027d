// Teacher notes: hidden from the class until asked for, shown under the
// lesson text, and gathered with every lesson into the printable handbook.

#include "ui/handbook.h"
#include "ui/lessons_dock.h"

#include "lessons/lesson_loader.h"

#include <QAction>
#include <QTest>
#include <QTextBrowser>

using namespace forcelab;

class GuiTeacherTest : public QObject {
    Q_OBJECT
private slots:
    void notesAreHiddenUntilAskedFor();
    void handbookHoldsEveryLessonAndItsNotes();
};

namespace {

Lesson noted()
{
    Lesson l;
    l.id = QStringLiteral("bounce");
    l.title = QStringLiteral("Bouncing");
    l.stage = 8;
    l.text = QStringLiteral("<p>A ball bounces.</p>");
    l.challenges = {QStringLiteral("How high is the second bounce?")};
    l.teacher.goal = QStringLiteral("Each bounce keeps e squared of the height.");
    l.teacher.minutes = 15;
    l.teacher.misconceptions = {QStringLiteral("The ball loses the same height every bounce.")};
    l.teacher.answers = {QStringLiteral("0.64 x 300 = 192 px")};
    return l;
}

} // namespace

void GuiTeacherTest::notesAreHiddenUntilAskedFor()
{
    LessonsDock dock;
    dock.setCurrentLesson(noted());
    QVERIFY(!dock.teacherNotesAction()->isChecked());
    QVERIFY(!dock.textBrowser()->toPlainText().contains(QStringLiteral("192 px")));
    dock.teacherNotesAction()->setChecked(true);
    const QString shown = dock.textBrowser()->toPlainText();
    QVERIFY2(shown.contains(QStringLiteral("192 px")) && shown.contains(QStringLiteral("same height every bounce")) &&
                 shown.contains(QStringLiteral("about 15 minutes")),
             qPrintable(shown));
    dock.teacherNotesAction()->setChecked(false);
    QVERIFY(!dock.textBrowser()->toPlainText().contains(QStringLiteral("192 px")));
}

void GuiTeacherTest::handbookHoldsEveryLessonAndItsNotes()
{
    const QString one = handbookHtml({noted()});
    QVERIFY(one.contains(QStringLiteral("0.64 x 300 = 192 px")));
    QVERIFY(one.contains(QStringLiteral("How high is the second bounce?")));
    const QString all = builtInHandbookHtml();
    for (const QString& file : LessonLoader::builtInFiles()) {
        const LoadResult r = LessonLoader::loadFile(file);
        QVERIFY(r.ok());
        QVERIFY2(all.contains(r.lesson->title.toHtmlEscaped()), qPrintable(r.lesson->title));
    }
    QCOMPARE(all.count(QStringLiteral("<section>")), LessonLoader::builtInFiles().size());
}

QTEST_MAIN(GuiTeacherTest)
#include "test_gui_teacher.moc"
