#pragma once
// Every sentence a lesson says with a number or a comparison in it ("twice",
// "within 1 %", "never", "all") is either backed by a claim that measures
// it, or listed in the lesson's "not_measured" with the reason it is not
// about this scene (a question, an instruction, a formula, a setting,
// something elsewhere) or why no measurement covers it. `forcelab-cli check`
// fails a lesson otherwise, so a teacher reading an answer aloud never reads
// a number the scene on the projector contradicts.
//
// A claim or a not_measured entry points at its sentence by quoting it:
// "says" is a piece of the lesson's words, or pieces joined by "…", found in
// that order in one text (the teaching text, a challenge, a question or a
// teacher note), compared without markup, spacing or letter case.

#include "lesson.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace forcelab::lessons {

/// One sentence of a lesson's words.
struct LessonSentence {
    QString field;             ///< where it is: "text", "challenges.2", "teacher.answers.0", "predict.1.ask", …
    QString text;              ///< the sentence without markup
    QString trigger;           ///< the first number or comparison word in it; empty when it has none
    std::vector<int> claims;   ///< the claims whose "says" lies in it
    std::vector<int> notMeasured; ///< the not_measured entries whose "says" lies in it
};

struct SentenceReport {
    std::vector<LessonSentence> sentences; ///< every sentence of the lesson, in reading order
    /// One line each, "field: what is wrong": a quote not found in the
    /// lesson, a sentence with a number that nothing backs, a setting that
    /// is not in the scene.
    QStringList problems;
};

/// Reads every text of the lesson sentence by sentence, in the language it
/// shows (lesson.language), and checks that each one with a number or a
/// comparison is backed.
SentenceReport checkSentences(const Lesson& lesson);

/// The first number ("0.9", "1/60", "²") or comparison word ("twice",
/// "never", "faster") in `sentence`, or an empty string. In another
/// language than English: its first number ("0,9" in German), since the
/// comparison words are checked in the English it translates.
QString numberOrComparison(const QString& sentence, const QString& language = QStringLiteral("en"));

/// The numbers of a plain text as values, in order, each a word of its own
/// ("300", "0.9", "1,200", "1/60" as 1/60; not the 2 of "2D" or "RK4"),
/// read the way `language` writes them: "0,9" and "1.200" where it writes
/// a decimal comma (German, Spanish). A sign is not part of the value.
std::vector<double> numberValues(const QString& plainText, const QString& language);

/// `text` (lesson markup) as plain sentences, in order.
QStringList splitSentences(const QString& text);

/// A field path as a reader says it: "text" → "text", "challenges.2" →
/// "challenge 3", "teacher.answers.0" → "answer 1", "predict.0.ask" →
/// "question 1".
QString fieldLabel(const QString& field);

} // namespace forcelab::lessons
