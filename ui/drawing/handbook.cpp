#include "handbook.h"

#include "lessons/lesson_languages.h"
#include "lessons/lesson_loader.h"
#include "lessons/lesson_markup.h"

#include <QCoreApplication>
#include <QLocale>
#include <QObject>
#include <QTextDocument>

namespace forcelab {

namespace {

// A lesson's words as HTML that loads nothing: the markup subset, with
// pictures as their names and without links (the handbook is a file a
// browser opens, far from the lesson's folder).
QString prose(const QString& text)
{
    return lessons::markupToPlainText(text).toHtmlEscaped();
}

QString list(const QStringList& items, const char* tag)
{
    QString html = QStringLiteral("<%1>").arg(QLatin1String(tag));
    for (const QString& item : items)
        html += QStringLiteral("<li>%1</li>").arg(prose(item));
    return html + QStringLiteral("</%1>").arg(QLatin1String(tag));
}

QString lessonText(const Lesson& lesson)
{
    return lessons::markupToHtml(lesson.text, false, false).html;
}

} // namespace

QString languageName(const QString& code)
{
    if (code == QLatin1String("en"))
        return QCoreApplication::translate("Language", "English");
    if (code == QLatin1String("de"))
        return QCoreApplication::translate("Language", "German");
    if (code == QLatin1String("es"))
        return QCoreApplication::translate("Language", "Spanish");
    const QString own = QLocale(code).nativeLanguageName();
    return own.isEmpty() ? code : own;
}

QString lessonLanguageNote(const Lesson& lesson)
{
    return QCoreApplication::translate("Language",
                                       "This lesson is not written in your language yet: its text is shown in %1.")
        .arg(languageName(lesson.language));
}

QString teacherNotesHtml(const Lesson& lesson)
{
    const TeacherNotes& t = lesson.teacher;
    if (t.empty() && lesson.claims.empty())
        return {};
    QString html;
    if (!t.goal.isEmpty() || t.minutes > 0) {
        html += QStringLiteral("<p><b>%1</b> %2").arg(QObject::tr("Goal:"), prose(t.goal));
        if (t.minutes > 0)
            html += QStringLiteral(" <i>(%1)</i>").arg(QObject::tr("about %1 minutes").arg(t.minutes));
        html += QStringLiteral("</p>");
    }
    if (!t.answers.isEmpty()) {
        html += QStringLiteral("<p><b>%1</b></p><ol>").arg(QObject::tr("Expected answers"));
        for (qsizetype i = 0; i < t.answers.size(); ++i)
            html += QStringLiteral("<li><i>%1</i><br>%2</li>")
                        .arg(prose(lesson.challenges.value(i)), prose(t.answers[i]));
        html += QStringLiteral("</ol>");
    }
    if (!t.misconceptions.isEmpty())
        html += QStringLiteral("<p><b>%1</b></p>").arg(QObject::tr("Common misconceptions")) + list(t.misconceptions, "ul");
    if (!lesson.claims.empty()) {
        QStringList claims;
        for (const sim::Claim& c : lesson.claims)
            claims << QString::fromStdString(c.text);
        claims.removeDuplicates(); // several measurements may back one sentence
        html += QStringLiteral("<p><b>%1</b></p>").arg(QObject::tr("What the scene is checked to show")) + list(claims, "ul");
    }
    return html;
}

QString handbookHtml(const QList<Lesson>& lessons, const QString& language)
{
    QString html = QStringLiteral("<!DOCTYPE html><html lang='%1'><head><meta charset='utf-8'><title>%2</title><style>"
                                  "body{font-family:sans-serif;max-width:46em;margin:2em auto;line-height:1.45;}"
                                  "section{page-break-after:always;border-top:2px solid #333;margin-top:2em;}"
                                  ".stage{color:#555;} .notes{background:#f4f4f4;padding:0.5em 1em;}"
                                  "</style></head><body>")
                       .arg(language, QObject::tr("ForceLab: teacher's handbook"));
    html += QStringLiteral("<h1>%1</h1><p>%2</p>")
                .arg(QObject::tr("ForceLab: teacher's handbook"),
                     QObject::tr("One section per lesson: the goal, the time it takes, the text students read, the "
                                 "challenges with their expected answers, the misconceptions to expect, and what the "
                                 "scene is checked to show (forcelab-cli check)."));
    for (const Lesson& lesson : lessons) {
        html += QStringLiteral("<section><h2>%1</h2><p class='stage'>%2</p>")
                    .arg(prose(lesson.title),
                         lesson.stage == 0 ? QObject::tr("Showcase")
                         : lesson.stage <= 29 ? QObject::tr("Stage %1 of 29").arg(lesson.stage)
                                              : QObject::tr("Beyond the course"));
        if (lesson.language != language)
            html += QStringLiteral("<p><i>%1</i></p>").arg(lessonLanguageNote(lesson).toHtmlEscaped());
        html += lessonText(lesson);
        if (!lesson.challenges.isEmpty())
            html += QStringLiteral("<h3>%1</h3>").arg(QObject::tr("Challenges")) + list(lesson.challenges, "ol");
        const QString notes = teacherNotesHtml(lesson);
        if (!notes.isEmpty())
            html += QStringLiteral("<h3>%1</h3><div class='notes'>%2</div>").arg(QObject::tr("For the teacher"), notes);
        html += QStringLiteral("</section>");
    }
    return html + QStringLiteral("</body></html>");
}

QString builtInHandbookHtml(const QString& language)
{
    QList<Lesson> lessons;
    for (const QString& file : LessonLoader::builtInFiles())
        if (const LoadResult r = LessonLoader::loadFile(file); r.ok())
            lessons << lessons::shownIn(*r.lesson, language);
    return handbookHtml(lessons, language);
}

} // namespace forcelab
