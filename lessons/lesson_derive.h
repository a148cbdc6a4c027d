#pragma once
// A new lesson made from the lesson on screen and the scene as it is now
// (File > Save Scene as Lesson…). The old lesson's title, text and
// questions were written for the old scene; a saved scene that kept them
// would reopen under the old title and fail `forcelab-cli check`. So a
// derived lesson gets:
//
// - its own title and text, typed by the teacher. The text is plain text:
//   it is escaped, blank lines start a new paragraph, a single line break
//   is a line break. It must pass the sentence check (sentence_check.h)
//   on its own: a typed sentence with a number or a comparison word that
//   nothing measures makes the lesson refused (see unmeasuredSentences()).
//   The one exception is creditSentence(), which names the old lesson and
//   is listed as not measured because it is about another lesson.
// - its own id (never the old one) and the stage kDerivedStage: beyond the
//   course, since it is not one of the course's lessons.
// - the old claims that still hold on the new scene and whose sentence
//   stands in the old teaching text (or in teacher notes that are kept). Each
//   such sentence, exactly as the claim quotes it, is listed under the typed
//   text, so the claim still has its sentence and a student reads only what
//   was measured. A claim whose sentence was in a challenge or a teacher
//   answer is dropped: those answer challenges the derived lesson does not
//   keep.
// - the prediction questions whose claim is kept (renumbered to the new
//   claim order), while every sentence of them with a number is still backed.
// - no challenges and no teacher answers (they are about the old text).
//   The teacher's goal, minutes and misconceptions only when asked for,
//   and of those only the ones whose numbers are still backed.
// - the old "not_measured" entries whose sentence is still in the lesson.
// - the controls, overlays and comparison panes, which are about the view.
//
// So the saved file loads (`forcelab-cli validate`) and passes
// `forcelab-cli check`; DerivedLesson says what was dropped and why.

#include "lesson.h"

#include "sim/studies/claims.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace forcelab::lessons {

/// The stage of a derived lesson: beyond the course (docs/lessons.md:
/// 0 is the showcase, 1–29 the course, above 29 beyond it).
inline constexpr int kDerivedStage = 99;

/// What the teacher chose in the Save Scene as Lesson dialog.
struct DeriveChoices {
    QString title;                 ///< plain text
    QString text;                  ///< plain text; blank lines between paragraphs
    bool keepTeacherNotes = false; ///< keep the goal, minutes and misconceptions
    /// Wished ids, best first (e.g. the file's name); the first valid one
    /// that is not the old lesson's id is used, else one made from the title.
    QStringList ids;
};

struct DroppedClaim {
    int index = 0;       ///< in the old lesson's claims
    QString says;        ///< the claim's sentence
    QString why;         ///< "measured 14.2 px/s, stated 25.2 px/s ± 0.05 px/s", or why it was not kept
    bool failed = false; ///< it was measured on the new scene and does not hold
};

struct DroppedPrediction {
    int index = 0;       ///< in the old lesson's questions
    QString ask;
    QString why;
};

struct DerivedLesson {
    Lesson lesson;
    std::vector<DroppedClaim> droppedClaims;
    std::vector<DroppedPrediction> droppedPredictions;
    QStringList droppedNotes;     ///< teacher notes left out because a number in them is no longer backed
    /// Why the lesson cannot be saved (a typed sentence with a number no
    /// claim measures, an empty title, a text over the limit); empty when it can.
    QStringList problems;
    bool ok() const { return problems.isEmpty(); }
    bool cancelled = false;       ///< the progress callback stopped a claim's run
};

/// The sentence the dialog starts the text with: Based on the lesson “TITLE”.
QString creditSentence(const Lesson& from);

/// The dialog's starting choices: title "Based on TITLE", text creditSentence().
DeriveChoices defaultDeriveChoices(const Lesson& from);

/// Plain typed text as lesson markup: escaped, paragraphs at blank lines.
QString plainToMarkup(const QString& plain);

/// The typed sentences that have a number or a comparison word and that
/// the derived lesson has nothing to back with (every one but
/// creditSentence(from)). The dialog shows them and does not save.
QStringList unmeasuredSentences(const Lesson& from, const QString& plainText);

/// A valid id (^[A-Za-z0-9_-]{1,64}$) that is not `avoid`: the first of
/// `wishes` that is one, else one made from `title`, else "saved-scene".
QString deriveId(const QStringList& wishes, const QString& title, const QString& avoid);

/// The lesson made from `from` and `scene`, with what was dropped. Runs
/// every claim of `from` on `scene` (sim::checkClaim), so it takes as long
/// as `forcelab-cli check` on the lesson; `progress` (share of the claims
/// done, 0 to 1) may stop it, and then the result is `cancelled`.
DerivedLesson deriveLesson(const Lesson& from, const sim::Scene& scene, const DeriveChoices& choices,
                           const sim::ClaimProgress& progress = {});

/// One paragraph for a status bar or a message box: what was saved and
/// which claims and questions were dropped, by their sentences.
QString deriveSummary(const DerivedLesson& derived);

} // namespace forcelab::lessons
