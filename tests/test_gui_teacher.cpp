// Teacher notes: hidden from the class until asked for, shown under the
// lesson text, and gathered with every lesson into the printable handbook.

#include "ui/drawing/handbook.h"
#include "ui/docks/lessons_dock.h"

#include "lessons/lesson_languages.h"
#include "lessons/lesson_loader.h"
#include "lessons/lesson_markup.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QUrl>

#include <sys/stat.h>
#include <QTest>
#include <QTextBrowser>

using namespace forcelab;

class GuiTeacherTest : public QObject {
    Q_OBJECT
private slots:
    void notesAreHiddenUntilAskedFor();
    void handbookHoldsEveryLessonAndItsNotes();
    void lessonPaneShowsOnlyTheLessonsOwnPictures();
    void linksOpenOnlyWebPagesAndOnlyWhenAsked();
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
    // In German: every lesson's German title, text and answers, and no
    // lesson says it is shown in another language.
    const QString german = builtInHandbookHtml(QStringLiteral("de"));
    QVERIFY(german.contains(QStringLiteral("<html lang='de'>")));
    for (const QString& file : LessonLoader::builtInFiles()) {
        const Lesson de = lessons::shownIn(*LessonLoader::loadFile(file).lesson, QStringLiteral("de"));
        QCOMPARE(de.language, QStringLiteral("de"));
        QVERIFY2(german.contains(de.title.toHtmlEscaped()), qPrintable(de.title));
        for (const QString& answer : de.teacher.answers)
            QVERIFY2(german.contains(lessons::markupToPlainText(answer).toHtmlEscaped()), qPrintable(answer));
    }
    QCOMPARE(german.count(QStringLiteral("<section>")), LessonLoader::builtInFiles().size());
    QVERIFY(!german.contains(lessonLanguageNote(Lesson{})));
    // A lesson without German says so in the handbook.
    const QString mixed = handbookHtml({noted()}, QStringLiteral("de"));
    QVERIFY(mixed.contains(lessonLanguageNote(noted()).toHtmlEscaped()));
}

// The pane serves a picture only from the lesson's own folder, from a
// regular file within the size limits; anything else is named where the
// picture would be, and no other resource is read. Before, a FIFO named in
// an <img> blocked the window for ever and /dev/zero filled the memory.
void GuiTeacherTest::lessonPaneShowsOnlyTheLessonsOwnPictures()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QImage red(20, 10, QImage::Format_RGB32);
    red.fill(Qt::red);
    QVERIFY(red.save(dir.filePath(QStringLiteral("pic.png"))));
    QImage huge(3000, 4, QImage::Format_RGB32);
    huge.fill(Qt::blue);
    QVERIFY(huge.save(dir.filePath(QStringLiteral("huge.png"))));
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath(QStringLiteral("fifo.png"))).constData(), 0600) == 0);
    QTemporaryDir outside;
    QVERIFY(red.save(outside.filePath(QStringLiteral("far.png"))));
    QVERIFY(QFile::link(outside.filePath(QStringLiteral("far.png")), dir.filePath(QStringLiteral("link.png"))));

    Lesson l = noted();
    l.source = dir.filePath(QStringLiteral("lesson.json"));
    l.text = QStringLiteral("<p>A <img src=\"pic.png\" alt=\"red\"> B <img src=\"fifo.png\"> C <img src=\"huge.png\"> "
                            "D <img src=\"link.png\"> E <img src=\"none.png\"></p>");
    LessonsDock dock;
    dock.setCurrentLesson(l); // returns: the FIFO is never opened
    QTextDocument* doc = dock.textBrowser()->document();
    const QImage shown = doc->resource(QTextDocument::ImageResource, QUrl(QStringLiteral("pic.png"))).value<QImage>();
    QCOMPARE(shown.size(), QSize(20, 10));
    QCOMPARE(shown.pixelColor(5, 5), QColor(Qt::red));
    for (const char* name : {"fifo.png", "huge.png", "link.png", "none.png", "/etc/hostname", "file:///etc/hostname"})
        QCOMPARE(doc->resource(QTextDocument::ImageResource, QUrl(QString::fromLatin1(name))).value<QImage>().size(),
                 QSize(1, 1)); // the blank the pane answers with, never the file
    const QString text = dock.textBrowser()->toPlainText();
    for (const char* why : {"fifo.png: not a file", "huge.png: 3000 x 4 px is larger than 2048 x 2048 px",
                            "link.png: leads out of the lesson's folder", "none.png: not in the lesson's folder"})
        QVERIFY2(text.contains(QString::fromUtf8(why)), qPrintable(text));
}

// A link opens a web page in the browser after the reader says yes, and
// nothing else ever: not a local path, not a file URL, not inside the pane.
void GuiTeacherTest::linksOpenOnlyWebPagesAndOnlyWhenAsked()
{
    LessonsDock dock;
    Lesson l = noted();
    l.text = QStringLiteral("<p><a href=\"https://example.org/orbits\">orbits</a></p>");
    dock.setCurrentLesson(l);
    LessonTextView* view = dock.textBrowser();
    QList<QUrl> asked, opened;
    bool answer = true;
    view->setConfirmLink([&](const QUrl& url) {
        asked << url;
        return answer;
    });
    view->setOpenLink([&](const QUrl& url) { opened << url; });
    const QString before = view->toPlainText();
    for (const char* target : {"/etc/passwd", "file:///etc/passwd", "etc/passwd", "https:///nohost"})
        emit view->anchorClicked(QUrl(QString::fromLatin1(target)));
    QVERIFY(asked.isEmpty() && opened.isEmpty());
    QCOMPARE(view->toPlainText(), before); // nothing was opened in the pane
    emit view->anchorClicked(QUrl(QStringLiteral("https://example.org/orbits")));
    QCOMPARE(asked.size(), 1);
    QCOMPARE(opened, QList<QUrl>{QUrl(QStringLiteral("https://example.org/orbits"))});
    answer = false;
    emit view->anchorClicked(QUrl(QStringLiteral("https://example.org/orbits")));
    QCOMPARE(asked.size(), 2);
    QCOMPARE(opened.size(), 1);
}

QTEST_MAIN(GuiTeacherTest)
#include "test_gui_teacher.moc"
