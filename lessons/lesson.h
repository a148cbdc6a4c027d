#pragma once
// A lesson: the scene it simulates plus what the workbench shows around it.
// Plain data: the loader fills it from a lesson file, the writer turns it back
// into one, the workbench and the CLI read it.

#include "sim/studies/claims.h"
#include "sim/world/scene.h"

#include <QString>
#include <QStringList>
#include <QMap>

#include <optional>
#include <vector>

namespace forcelab {

/// What a teacher needs and a class does not see: shown in the Lessons dock's
/// Teacher section (hidden unless asked for) and in the printable handbook.
struct TeacherNotes {
    QString goal;               ///< what students should take away, in one or two sentences
    int minutes = 0;            ///< minutes the lesson takes in class (0: not stated)
    QStringList misconceptions; ///< wrong ideas students often bring, each with what the scene shows instead
    QStringList answers;        ///< the expected answer to each challenge, in the challenges' order
    bool empty() const { return goal.isEmpty() && minutes == 0 && misconceptions.isEmpty() && answers.isEmpty(); }
    friend bool operator==(const TeacherNotes&, const TeacherNotes&) = default;
};

/// A second run of the same scene beside the live one, with a few settings
/// of its own (lesson 09: the same drop with the mirror and the exact wall
/// models), so a class sees the models side by side.
struct ComparePane {
    QString label; ///< shown on the pane, e.g. "mirror"
    std::vector<std::pair<std::string, double>> set; ///< key path and value (choices as their index), as claims' "set"
};

/// A question a lesson asks before it runs ("How high will the second
/// bounce be?"). The answer is measured by one of the lesson's claims, with
/// the claim's own rule, so the question and the text can never disagree.
struct Prediction {
    QString ask;                ///< the question
    int claim = 0;              ///< index into the lesson's claims; its measurement answers the question
    QStringList choices;        ///< optional answers to pick from (empty: the student types a number)
    std::vector<double> values; ///< each choice's value in the claim's unit; the measured one is the nearest
};

/// A sentence of the lesson with a number or a comparison that no claim
/// checks, and why none can: `forcelab-cli check` fails a lesson in which
/// such a sentence is neither backed by a claim nor listed here
/// (lessons/sentence_check.h).
struct NotMeasured {
    /// Why the sentence is not a claim about this scene.
    enum class Because {
        Question,    ///< it asks; the answer is a teacher answer, checked on its own
        Instruction, ///< it tells the class what to set or do; its numbers are what to type in
        Formula,     ///< a calculation, a definition or the program's rule: true whatever the scene does
        Setting,     ///< it repeats this scene's settings; the check finds each of its numbers in the scene
        Elsewhere,   ///< about the world outside, another program or another lesson, not this scene
        Unmeasured,  ///< about this scene, but no claim measurement covers it; `why` says how it was checked
    };
    QString says;   ///< the sentence, or pieces of it joined by "…", as the lesson writes it
    Because because = Because::Question;
    QString why;    ///< required for Unmeasured: how the sentence was checked and what measurement it lacks
    friend bool operator==(const NotMeasured&, const NotMeasured&) = default;
};

/// The file's names of NotMeasured::Because, in its order.
inline constexpr const char* kNotMeasuredReasons[] = {"question", "instruction", "formula",
                                                      "setting",  "elsewhere",   "unmeasured"};

/// The scale at which a lesson speaks SI (issue #36): sliders, readouts and
/// tables show m, m/s, kg, N and J while the world keeps working in px.
struct LessonUnits {
    double pxPerMetre = 100.0; ///< px per m: how many pixels stand for one metre
    double kgPerMass = 1.0;    ///< kg per mass unit: what one of the lesson's mass units weighs
    friend bool operator==(const LessonUnits&, const LessonUnits&) = default;
};

/// A lesson's words in one language: every field a reader sees, in the
/// same order and with the same counts as the lesson's own, so each
/// translated claim quotes the translated sentence it backs
/// (lessons/lesson_languages.h).
struct LessonWords {
    QString title;
    QString text;
    QStringList challenges;
    QStringList predictAsks;                ///< one per question
    std::vector<QStringList> predictChoices; ///< one list per question (empty: the student types a number)
    QString goal;                           ///< the teacher's goal
    QStringList misconceptions;
    QStringList answers;
    QStringList claims;                     ///< each claim's "says"
    QStringList notMeasuredSays;            ///< each not_measured entry's "says"
    QStringList notMeasuredWhy;             ///< its "why" (empty where the lesson's own has none)
    QStringList compare;                    ///< each compare pane's label
    friend bool operator==(const LessonWords&, const LessonWords&) = default;
};

struct Lesson {
    int format = 1;
    QString id;          ///< e.g. "gravity"; also the built-in name for `forcelab-cli run`
    QString title;
    int stage = 0;       ///< curriculum stage, 0 for the showcase, > 29 beyond the tutorial
    QString text;        ///< teaching text (simple rich text)
    QStringList challenges;
    QStringList controls; ///< parameter names shown first in the Parameters dock
    QStringList overlays; ///< overlays switched on, e.g. "velocity", "readout"
    QStringList tools;    ///< panels the text and challenges use, e.g. "stopwatch" (lesson_tools.h)
    /// What the text says about the scene, as measurements `forcelab-cli
    /// check` runs (sim/studies/claims.h); each claim's text is the lesson's sentence.
    std::vector<sim::Claim> claims;
    /// Sentences with numbers or comparisons that are not claims, and why.
    std::vector<NotMeasured> notMeasured;
    TeacherNotes teacher;
    /// Questions asked before the run, each answered by a claim.
    std::vector<Prediction> predict;
    /// Runs shown beside the live one (at most kMaxComparePanes).
    std::vector<ComparePane> compare;
    static constexpr int kMaxComparePanes = 3;
    /// "student_code": a student's own versions of the course's JavaScript
    /// files (file name, e.g. "walls.js" → its text), kept with the lesson so
    /// the student can carry on where they stopped. Run only in the script
    /// sandbox (ui/script), and only when the student presses Run.
    QMap<QString, QString> studentCode;
    /// "units": shown in SI at this scale; absent, the lesson speaks pixels.
    std::optional<LessonUnits> units;
    /// The language of the words in the fields above ("en", "de", "es"):
    /// the file's own (its "language", English when absent) until
    /// lessons::showIn() puts another one of `languages` in their place.
    QString language = QStringLiteral("en");
    /// The language of the file's own words, which the writer writes back.
    QString fileLanguage = QStringLiteral("en");
    /// "languages": the words in other languages, by code; the words of
    /// `language` are not in it while they are shown.
    QMap<QString, LessonWords> languages;
    QString source;      ///< where it was loaded from (file path or ":/lessons/…")
    sim::Scene scene;
};

} // namespace forcelab
