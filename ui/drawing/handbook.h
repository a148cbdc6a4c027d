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

/// The whole course as one HTML document, lessons in the order given.
QString handbookHtml(const QList<Lesson>& lessons);

/// The handbook of the built-in lessons, in course order.
QString builtInHandbookHtml();

} // namespace forcelab
