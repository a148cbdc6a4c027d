#include "lessons/lesson_derive.h"

#include "lessons/lesson_limits.h"
#include "lessons/lesson_loader.h"
#include "lessons/lesson_markup.h"
#include "lessons/sentence_check.h"

#include <QObject>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace forcelab::lessons {

namespace {

/// Above the kept claims' sentences in the derived text. No number and no
/// comparison word in it, so it needs nothing to back it.
const char* const kKeptHeading = "Said in the lesson this one is based on, and measured again on this scene:";

QString quotedText(const QString& s)
{
    return QStringLiteral("“%1”").arg(s);
}

/// The claim's quote as a line of the derived text: a capital first, a
/// full stop last, its characters escaped. The quote's words are unchanged,
/// so the sentence check still finds them (it ignores case and markup).
QString keptLine(const std::string& says)
{
    QString line = QString::fromStdString(says).trimmed();
    if (!line.isEmpty())
        line[0] = line[0].toUpper();
    if (!line.isEmpty() && !QStringLiteral(".!?").contains(line.back()))
        line += QLatin1Char('.');
    return line.toHtmlEscaped();
}

/// The kept claims' lines under their heading, as markup.
QString keptList(const QStringList& lines)
{
    if (lines.isEmpty())
        return {};
    return QStringLiteral("<p>%1</p><ul><li>%2</li></ul>")
        .arg(QString::fromUtf8(kKeptHeading), lines.join(QStringLiteral("</li><li>")));
}

/// Whether the sentence check finds `claim`'s quote in `lines`.
bool quotedIn(const QStringList& lines, const sim::Claim& claim)
{
    if (lines.isEmpty())
        return false;
    Lesson probe;
    probe.text = keptList(lines);
    probe.claims = {claim};
    const SentenceReport report = checkSentences(probe);
    return std::any_of(report.sentences.begin(), report.sentences.end(),
                       [](const LessonSentence& s) { return !s.claims.empty(); });
}

/// The fields of `from` each claim's quote lies in ("text", "challenges.2", …).
std::vector<QStringList> claimFields(const Lesson& from)
{
    std::vector<QStringList> fields(from.claims.size());
    for (const LessonSentence& s : checkSentences(from).sentences)
        for (const int k : s.claims)
            if (k >= 0 && std::size_t(k) < fields.size() && !fields[std::size_t(k)].contains(s.field))
                fields[std::size_t(k)] << s.field;
    return fields;
}

bool isNoteField(const QString& field)
{
    return field == QLatin1String("teacher.goal") || field.startsWith(QLatin1String("teacher.misconceptions."));
}

QString labels(const QStringList& fields)
{
    QStringList out;
    for (const QString& f : fields)
        if (const QString l = fieldLabel(f); !out.contains(l))
            out << l;
    return out.join(QStringLiteral(", "));
}

/// The number in a field path after `prefix` ("predict.3.ask", "predict.") → 3.
int indexAfter(const QString& field, const QString& prefix)
{
    return field.mid(prefix.size()).section(QLatin1Char('.'), 0, 0).toInt();
}

} // namespace

QString creditSentence(const Lesson& from)
{
    return QStringLiteral("Based on the lesson “%1”.").arg(markupToPlainText(from.title).simplified());
}

DeriveChoices defaultDeriveChoices(const Lesson& from)
{
    DeriveChoices c;
    c.title = QStringLiteral("Based on %1").arg(markupToPlainText(from.title).simplified());
    c.text = creditSentence(from);
    return c;
}

QString plainToMarkup(const QString& plain)
{
    QString text = plain;
    text.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(QLatin1Char('\r'), QLatin1Char('\n'));
    static const QRegularExpression blank(QStringLiteral("\\n[ \\t]*\\n"));
    QString out;
    for (const QString& paragraph : text.split(blank)) {
        const QString p = paragraph.trimmed();
        if (p.isEmpty())
            continue;
        QStringList lines;
        for (const QString& line : p.split(QLatin1Char('\n')))
            lines << line.trimmed().toHtmlEscaped();
        out += QStringLiteral("<p>%1</p>").arg(lines.join(QStringLiteral("<br>")));
    }
    return out;
}

QStringList unmeasuredSentences(const Lesson& from, const QString& plainText)
{
    const QString credit = creditSentence(from);
    QStringList out;
    for (const QString& s : splitSentences(plainToMarkup(plainText)))
        if (!numberOrComparison(s, from.language).isEmpty() && !credit.contains(s, Qt::CaseInsensitive))
            out << s;
    return out;
}

QString deriveId(const QStringList& wishes, const QString& title, const QString& avoid)
{
    static const QRegularExpression valid(QStringLiteral("^[A-Za-z0-9_-]{1,64}$"));
    for (const QString& w : wishes)
        if (valid.match(w).hasMatch() && w != avoid)
            return w;
    QString id;
    for (const QChar c : markupToPlainText(title).toLower()) {
        const bool keep = c.unicode() < 128 && c.isLetterOrNumber();
        if (keep)
            id += c;
        else if (!id.isEmpty() && !id.endsWith(QLatin1Char('-')))
            id += QLatin1Char('-');
    }
    id = id.left(64);
    while (id.endsWith(QLatin1Char('-')))
        id.chop(1);
    if (id.isEmpty())
        id = QStringLiteral("saved-scene");
    if (id == avoid)
        id = id.left(58) + QStringLiteral("-saved");
    return id;
}

namespace {

/// A derived lesson as it is made: the lesson, what was dropped, and where
/// each kept claim and question was in the old lesson.
struct Deriving {
    const Lesson& from;
    const DeriveChoices& choices;
    DerivedLesson out;
    std::vector<int> claimFrom;   ///< old index of each kept claim
    std::vector<int> predictFrom; ///< old index of each kept question
    QStringList keptLines;        ///< the text's list of kept claims' sentences

    Lesson& lesson() { return out.lesson; }
    bool keepClaims(const sim::Scene& scene, const sim::ClaimProgress& progress);
    void keepPredictions();
    bool dropUnfound();
    bool dropUnbacked();
    void dropClaim(std::size_t k, const QString& why);
};

/// Why a claim cannot run on `scene`: more steps than a claim may take.
bool tooLong(const sim::Claim& claim, const sim::Scene& scene)
{
    double dt = scene.settings.time.dt, substeps = scene.settings.time.substeps;
    for (const auto& [key, value] : claim.set) {
        if (key == "time.dt")
            dt = value;
        else if (key == "time.substeps")
            substeps = value;
    }
    return !(dt > 0.0) || std::ceil(claim.at / dt) * std::max(1.0, substeps) > kMaxClaimSteps;
}

/// Runs every claim of the old lesson that can stay on `scene`; false when
/// `progress` stopped it.
bool Deriving::keepClaims(const sim::Scene& scene, const sim::ClaimProgress& progress)
{
    const std::vector<QStringList> fields = claimFields(from);
    const std::size_t n = from.claims.size();
    for (std::size_t k = 0; k < n; ++k) {
        const sim::Claim& claim = from.claims[k];
        const QString says = QString::fromStdString(claim.text);
        const QStringList& where = fields[k];
        const bool inText = where.contains(QStringLiteral("text"));
        const bool canStay = inText || std::any_of(where.begin(), where.end(), [&](const QString& f) {
                                 return (choices.keepTeacherNotes && isNoteField(f)) ||
                                        f.startsWith(QLatin1String("predict."));
                             });
        if (!canStay) {
            out.droppedClaims.push_back(
                {int(k), says,
                 where.isEmpty()
                     ? QStringLiteral("its sentence is not in the lesson")
                     : QStringLiteral("its sentence is in %1, which the new lesson does not keep").arg(labels(where))});
            continue;
        }
        if (tooLong(claim, scene)) {
            out.droppedClaims.push_back(
                {int(k), says, QStringLiteral("with this time step it would take more steps than a claim may run")});
            continue;
        }
        sim::ClaimProgress each;
        if (progress)
            each = [&progress, k, n](double done) { return progress((double(k) + done) / double(n)); };
        const sim::ClaimResult result = sim::checkClaim(scene, claim, each);
        if (result.cancelled)
            return false;
        if (!result.holds) {
            out.droppedClaims.push_back({int(k), says, QString::fromStdString(result.explanation), true});
            continue;
        }
        claimFrom.push_back(int(k));
        lesson().claims.push_back(claim);
        // A line of its own, unless the sentence check finds the quote in the
        // lines already listed: it marks only the first place a quote is, so a
        // second line with the same words would be left with nothing to back it.
        if (inText && !quotedIn(keptLines, claim))
            keptLines << keptLine(claim.text);
    }
    return true;
}

/// The questions whose answer is still measured, renumbered.
void Deriving::keepPredictions()
{
    for (std::size_t j = 0; j < from.predict.size(); ++j) {
        const Prediction& p = from.predict[j];
        const auto at = std::find(claimFrom.begin(), claimFrom.end(), p.claim);
        if (at == claimFrom.end()) {
            QString why = QStringLiteral("the claim that answers it was dropped");
            for (const DroppedClaim& d : out.droppedClaims)
                if (d.index == p.claim)
                    why += QStringLiteral(" (%1)").arg(d.why);
            out.droppedPredictions.push_back({int(j), markupToPlainText(p.ask), why});
            continue;
        }
        Prediction q = p;
        q.claim = int(at - claimFrom.begin());
        lesson().predict.push_back(q);
        predictFrom.push_back(int(j));
    }
}

/// Drops kept claim `k` and the questions it answers.
void Deriving::dropClaim(std::size_t k, const QString& why)
{
    Lesson& l = lesson();
    out.droppedClaims.push_back({claimFrom[k], QString::fromStdString(l.claims[k].text), why});
    l.claims.erase(l.claims.begin() + std::ptrdiff_t(k));
    claimFrom.erase(claimFrom.begin() + std::ptrdiff_t(k));
    for (std::size_t j = 0; j < l.predict.size();) {
        if (l.predict[j].claim == int(k)) {
            out.droppedPredictions.push_back({predictFrom[j], markupToPlainText(l.predict[j].ask),
                                              QStringLiteral("the claim that answers it was dropped")});
            l.predict.erase(l.predict.begin() + std::ptrdiff_t(j));
            predictFrom.erase(predictFrom.begin() + std::ptrdiff_t(j));
            continue;
        }
        if (l.predict[j].claim > int(k))
            --l.predict[j].claim;
        ++j;
    }
}

/// Drops one not_measured entry or claim whose sentence is no longer in
/// the lesson, or a setting entry whose numbers the scene no longer sets;
/// false when there is none.
bool Deriving::dropUnfound()
{
    Lesson& l = lesson();
    const SentenceReport report = checkSentences(l);
    std::vector<bool> claimFound(l.claims.size()), entryFound(l.notMeasured.size());
    for (const LessonSentence& s : report.sentences) {
        for (const int k : s.claims)
            claimFound[std::size_t(k)] = true;
        for (const int k : s.notMeasured)
            entryFound[std::size_t(k)] = true;
    }
    if (const auto e = std::find(entryFound.begin(), entryFound.end(), false); e != entryFound.end()) {
        l.notMeasured.erase(l.notMeasured.begin() + (e - entryFound.begin()));
        return true;
    }
    static const QRegularExpression entryProblem(QStringLiteral("^not_measured\\.(\\d+):"));
    for (const QString& problem : report.problems)
        if (const auto m = entryProblem.match(problem); m.hasMatch()) {
            l.notMeasured.erase(l.notMeasured.begin() + m.captured(1).toInt());
            return true;
        }
    if (const auto c = std::find(claimFound.begin(), claimFound.end(), false); c != claimFound.end()) {
        dropClaim(std::size_t(c - claimFound.begin()), QStringLiteral("its sentence was in a teacher note that was left out"));
        return true;
    }
    return false;
}

/// Leaves out the question or teacher note holding the first sentence with
/// a number nothing backs any more; false when there is none. Such a
/// sentence in the typed text is a problem instead.
bool Deriving::dropUnbacked()
{
    Lesson& l = lesson();
    const SentenceReport report = checkSentences(l);
    const auto unbacked = std::find_if(report.sentences.begin(), report.sentences.end(), [](const LessonSentence& s) {
        return !s.trigger.isEmpty() && s.claims.empty() && s.notMeasured.empty();
    });
    if (unbacked == report.sentences.end())
        return false;
    const QString why =
        QStringLiteral("%1 says “%2”, which nothing measures any more").arg(quotedText(unbacked->text), unbacked->trigger);
    if (unbacked->field.startsWith(QLatin1String("predict."))) {
        const int j = indexAfter(unbacked->field, QStringLiteral("predict."));
        out.droppedPredictions.push_back({predictFrom[std::size_t(j)], markupToPlainText(l.predict[std::size_t(j)].ask), why});
        l.predict.erase(l.predict.begin() + j);
        predictFrom.erase(predictFrom.begin() + j);
        return true;
    }
    if (unbacked->field == QLatin1String("teacher.goal")) {
        out.droppedNotes << QStringLiteral("the goal: %1").arg(why);
        l.teacher.goal.clear();
        return true;
    }
    if (unbacked->field.startsWith(QLatin1String("teacher.misconceptions."))) {
        const int i = indexAfter(unbacked->field, QStringLiteral("teacher.misconceptions."));
        out.droppedNotes << QStringLiteral("misconception %1: %2").arg(i + 1).arg(why);
        l.teacher.misconceptions.removeAt(i);
        return true;
    }
    // In the typed text: unmeasuredSentences() has said so already, unless
    // the sentence check reads it differently.
    if (out.problems.isEmpty())
        out.problems << why;
    return false;
}

} // namespace

DerivedLesson deriveLesson(const Lesson& from, const sim::Scene& scene, const DeriveChoices& choices,
                           const sim::ClaimProgress& progress)
{
    Deriving d{from, choices, {}, {}, {}, {}};
    Lesson& l = d.lesson();
    l.format = from.format;
    // The teacher types in the language on the screen; the new lesson is
    // in that one language (the old translations are of the old text).
    l.language = l.fileLanguage = from.language;
    l.title = choices.title.simplified().toHtmlEscaped();
    l.id = deriveId(choices.ids, choices.title, from.id);
    l.stage = kDerivedStage;
    l.controls = from.controls;
    l.overlays = from.overlays;
    l.compare = from.compare;
    l.scene = scene;
    if (l.title.isEmpty())
        d.out.problems << QStringLiteral("The lesson needs a title.");
    for (const QString& s : unmeasuredSentences(from, choices.text))
        d.out.problems << QStringLiteral("%1 has a number or a comparison (“%2”) that no claim measures on this scene. "
                                         "Write it without, or add a claim to the file later.")
                              .arg(quotedText(s), numberOrComparison(s, from.language));

    if (!d.keepClaims(scene, progress)) {
        d.out.cancelled = true;
        d.out.problems << QStringLiteral("Stopped before every claim was measured.");
        return d.out;
    }
    l.text = plainToMarkup(choices.text) + keptList(d.keptLines);
    if (choices.keepTeacherNotes) {
        l.teacher.goal = from.teacher.goal;
        l.teacher.minutes = from.teacher.minutes;
        l.teacher.misconceptions = from.teacher.misconceptions;
    }
    d.keepPredictions();
    l.notMeasured = from.notMeasured;
    // The credit sentence names another lesson, so its numbers are not about this scene.
    const QString credit = creditSentence(from);
    for (const QString& s : splitSentences(plainToMarkup(choices.text)))
        if (!numberOrComparison(s, from.language).isEmpty() && credit.contains(s, Qt::CaseInsensitive))
            l.notMeasured.push_back(
                {s, NotMeasured::Because::Elsewhere, QStringLiteral("it names the lesson this one was made from")});

    // Until the sentence check has nothing to say: drop what is no longer
    // in the lesson, then whatever says a number nothing backs any more.
    // Each round drops one thing, so this ends.
    while (d.dropUnfound() || d.dropUnbacked()) {
    }

    if (const auto p = checkMarkup(l.title, kMaxProseChars))
        d.out.problems << QStringLiteral("The title: %1").arg(p->message);
    if (const auto p = checkMarkup(l.text, kMaxTextChars))
        d.out.problems << QStringLiteral("The text: %1").arg(p->message);
    if (d.out.problems.isEmpty()) {
        // What `forcelab-cli validate` reads: the file must load as it is saved.
        const LoadResult back = LessonLoader::loadBytes(saveLesson(l), l.id);
        if (!back.ok())
            d.out.problems << back.errors();
    }
    return d.out;
}

QString deriveSummary(const DerivedLesson& derived)
{
    const Lesson& l = derived.lesson;
    const int claims = int(l.claims.size() + derived.droppedClaims.size());
    const int questions = int(l.predict.size() + derived.droppedPredictions.size());
    QString s = QObject::tr("Kept %1 of %2 claims and %3 of %4 questions.")
                    .arg(l.claims.size())
                    .arg(claims)
                    .arg(l.predict.size())
                    .arg(questions);
    if (!derived.droppedClaims.empty()) {
        QStringList parts;
        for (const DroppedClaim& d : derived.droppedClaims)
            parts << QStringLiteral("%1 (%2)").arg(quotedText(d.says), d.why);
        s += QObject::tr(" Dropped claims: %1.").arg(parts.join(QStringLiteral("; ")));
    }
    if (!derived.droppedPredictions.empty()) {
        QStringList parts;
        for (const DroppedPrediction& d : derived.droppedPredictions)
            parts << QStringLiteral("%1 (%2)").arg(quotedText(d.ask), d.why);
        s += QObject::tr(" Dropped questions: %1.").arg(parts.join(QStringLiteral("; ")));
    }
    if (!derived.droppedNotes.isEmpty())
        s += QObject::tr(" Left out of the teacher notes: %1.").arg(derived.droppedNotes.join(QStringLiteral("; ")));
    return s;
}

} // namespace forcelab::lessons
