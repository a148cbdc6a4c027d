#pragma once
// The teacher's handbook: every lesson's goal, time, text, challenges with
// their expected answers, common misconceptions and the checked claims, as
// one printable HTML page. The Lessons dock's Teacher section shows the same
// notes for one lesson.

#include "lessons/lesson.h"

#include <QList>
#include <QString>

namespace forcelab {

/// The teacher notes of one lesson as an HTML fragment ("" when it has none).
QString teacherNotesHtml(const Lesson& lesson);

/// A language's name in the program's language ("German", "Deutsch").
QString languageName(const QString& code);
/// The line a reader sees over a lesson shown in another language than the
/// program's: "This lesson is not written in your language yet: its text is
/// shown in English."
QString lessonLanguageNote(const Lesson& lesson);

/// The whole course as one HTML document, lessons in the order given, for
/// readers of `language` (a lesson shown in another says so).
QString handbookHtml(const QList<Lesson>& lessons, const QString& language = QStringLiteral("en"));

/// The handbook of the built-in lessons, in course order, each in
/// `language` where it has it.
QString builtInHandbookHtml(const QString& language = QStringLiteral("en"));

} // namespace forcelab
