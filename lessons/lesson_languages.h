#pragma once
// A lesson in more than one language. A lesson file's own words are in its
// "language" (English when absent); "languages" holds the same words in
// other languages, field for field:
//
//   "languages": {"de": {"title": …, "text": …, "challenges": […],
//                        "predict": [{"ask": …, "choices": […]}],
//                        "teacher": {"goal": …, "misconceptions": […], "answers": […]},
//                        "claims": ["says", …], "not_measured": [{"says": …, "why": …}],
//                        "compare": ["label", …]}}
//
// Each translation has exactly the lesson's fields and counts, every field
// keeps the numbers of the lesson's own (as values, each language writing
// decimals its own way: 0,8 in German), and its claims quote its own
// sentences, so `forcelab-cli check` checks every language's sentences as
// it checks the lesson's own. A language a lesson lacks is shown in the
// file's own language, and the lesson panel says so.

#include "lesson.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace forcelab::lessons {

/// The most languages one file may carry besides its own.
inline constexpr int kMaxLessonLanguages = 32;

/// Whether `code` names a language as lesson files do: two or three small
/// letters ("de", "es"), optionally "-" and a region ("pt-BR").
bool isLanguageCode(const QString& code);

/// The words the lesson shows now.
LessonWords wordsOf(const Lesson& lesson);

/// Puts `code`'s words in the lesson's fields (the words shown before go
/// into `languages`). False, and nothing changed, when the lesson has no
/// words in `code`; showing the language already shown is true.
bool showIn(Lesson& lesson, const QString& code);

/// The lesson in `code` when it has that language, else in the file's own
/// language: what a reader of `code` is shown.
Lesson shownIn(const Lesson& lesson, const QString& code);

/// Why `words` cannot stand for `lesson`'s own words, one line per field
/// ("languages.de.challenges: 2 entries; the lesson has 3"); empty when it can.
QStringList shapeProblems(const Lesson& lesson, const LessonWords& words, const QString& path);

/// The numbers of a text as values, sorted, as the sentence check reads
/// them (lessons::numberValues): "0.8", "1,200" and "1/60" in English,
/// "0,8" and "1.200" in German and Spanish.
std::vector<double> numbersOf(const QString& plainText, const QString& language);

/// The fields of the translation `code` whose numbers differ from the same
/// field of the lesson's own words (`own`, in `ownLanguage`):
/// "languages.de.text: numbers 0.8, 400 where the lesson has 0.8, 500".
QStringList numberProblems(const LessonWords& own, const QString& ownLanguage, const LessonWords& translation,
                           const QString& code);

} // namespace forcelab::lessons
