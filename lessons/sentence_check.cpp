#include "sentence_check.h"

#include "lesson_markup.h"
#include "sim/world/parameters.h"

#include <QLocale>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace forcelab::lessons {

namespace {

using Span = std::pair<qsizetype, qsizetype>; ///< [begin, end) in a field's plain text

/// Markup as plain text: a line break between paragraphs and list items,
/// every other run of white space one space.
QString plainOf(const QString& markup)
{
    QString m = markup;
    m.replace(QStringLiteral("<li>"), QStringLiteral("\n<li>"), Qt::CaseInsensitive);
    const QString text = markupToPlainText(m);
    QString out;
    out.reserve(text.size());
    bool space = false, paragraph = false;
    for (const QChar c : text) {
        if (c == QLatin1Char('\n')) {
            paragraph = true;
            continue;
        }
        if (c.isSpace()) {
            space = true;
            continue;
        }
        if (!out.isEmpty() && (paragraph || space))
            out += paragraph ? QLatin1Char('\n') : QLatin1Char(' ');
        paragraph = space = false;
        out += c;
    }
    return out;
}

bool startsSentence(QChar c)
{
    static const QString openers = QStringLiteral("(\"“‘'[−-");
    return c.isUpper() || c.isDigit() || openers.contains(c);
}

/// Sentences of plain text: they end at a line break, or at ".", "!" or "?"
/// (and any closing brackets or quotes) followed by a space and a capital,
/// a digit or an opening bracket. "0.9", "e^(−1)" and "…makes" do not end one.
std::vector<Span> sentenceSpans(const QString& p)
{
    static const QString closers = QStringLiteral(")\"”’]'");
    std::vector<Span> spans;
    qsizetype start = 0;
    auto push = [&](qsizetype begin, qsizetype end) {
        while (begin < end && p[begin].isSpace())
            ++begin;
        while (end > begin && p[end - 1].isSpace())
            --end;
        if (end > begin)
            spans.emplace_back(begin, end);
    };
    for (qsizetype i = 0; i < p.size(); ++i) {
        if (p[i] == QLatin1Char('\n')) {
            push(start, i);
            start = i + 1;
            continue;
        }
        if (p[i] != QLatin1Char('.') && p[i] != QLatin1Char('!') && p[i] != QLatin1Char('?'))
            continue;
        qsizetype j = i + 1;
        while (j < p.size() && closers.contains(p[j]))
            ++j;
        if (j + 1 < p.size() && p[j] == QLatin1Char(' ') && startsSentence(p[j + 1])) {
            push(start, j);
            start = j + 1;
            i = j;
        }
    }
    push(start, p.size());
    return spans;
}

/// A number as a word of its own: "300", "0.9", "1,200", "−3", "1/60"; not
/// the digit of a name such as "rk4", "yoshida4" or "2d-axis". In a
/// language that writes a decimal comma (German, Spanish): "0,9", "1.200".
bool decimalComma(const QString& language)
{
    return QLocale(language).decimalPoint() == QStringLiteral(",");
}

const QRegularExpression& numberPattern(const QString& language = QStringLiteral("en"))
{
    static const QRegularExpression point(
        QStringLiteral(R"((?<![\p{L}\p{N}_.])[−-]?(\d{1,3}(?:,\d{3})+|\d+)(?:\.(\d+))?(?:/(\d+(?:\.\d+)?))?(?![\p{L}\p{N}_]|-\p{L}))"));
    static const QRegularExpression comma(
        QStringLiteral(R"((?<![\p{L}\p{N}_,.])[−-]?(\d{1,3}(?:[.\x{202F}\x{00A0}]\d{3})+|\d+)(?:,(\d+))?(?:/(\d+(?:,\d+)?))?(?![\p{L}\p{N}_]|-\p{L}))"));
    return decimalComma(language) ? comma : point;
}

const QRegularExpression& wordPattern()
{
    static const QRegularExpression re(
        QStringLiteral("\\b(two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|twenty|thirty|forty|fifty|"
                       "hundreds?|thousands?|millions?|dozens?|twice|half|halves|halve|halved|halving|double|doubles|"
                       "doubled|doubling|triples?|tripled|quarter|never|always|all|every|none|nothing|same|equal|"
                       "equals|exactly|constant|within|fewer|times|faster|slower|higher|lower|further|farther|"
                       "larger|smaller|bigger|longer|shorter|heavier|lighter|stronger|weaker|closer|more than|"
                       "less than)\\b|π|√"),
        QRegularExpression::CaseInsensitiveOption | QRegularExpression::UseUnicodePropertiesOption);
    return re;
}

/// The value of a number the pattern matched, and half its last digit's
/// place (how far a rounded value may be from the true one).
struct TextNumber {
    double value;
    double halfUlp;
};

std::vector<TextNumber> numbersIn(const QString& s, const QString& language)
{
    static const QRegularExpression separators(QStringLiteral("[.,\\x{202F}\\x{00A0}]"));
    std::vector<TextNumber> out;
    auto it = numberPattern(language).globalMatch(s);
    while (it.hasNext()) {
        const auto m = it.next();
        QString whole = m.captured(1);
        whole.remove(separators);
        const QString decimals = m.captured(2);
        double v = (whole + (decimals.isEmpty() ? QString() : QLatin1Char('.') + decimals)).toDouble();
        double half = 0.5 * std::pow(10.0, -double(decimals.size()));
        if (m.capturedLength(3) > 0) {
            const double d = QString(m.captured(3)).replace(QLatin1Char(','), QLatin1Char('.')).toDouble();
            if (d == 0.0)
                continue;
            v /= d;
            half = 1e-9 * std::abs(v);
        }
        out.push_back({v, half});
    }
    return out;
}

/// Every number the lesson file sets for its scene: the settings' rows, the
/// listed balls, the random balls and the ball count.
std::vector<double> sceneNumbers(const sim::Scene& scene)
{
    std::vector<double> v;
    for (const sim::Parameter& p : sim::parameters())
        if (p.get)
            v.push_back(p.get(scene.settings));
    for (const sim::Ball& b : scene.balls) {
        v.insert(v.end(), {b.position.x(), b.position.y(), b.velocity.x(), b.velocity.y(), b.radius, b.mass, b.charge});
        if (sim::hasOwnRestitution(b.restitution))
            v.push_back(b.restitution);
    }
    const sim::SpawnSettings& s = scene.spawn;
    v.insert(v.end(), {double(s.count), s.minRadius, s.maxRadius, s.minSpeed, s.maxSpeed, s.perStep, double(s.maxCount),
                       double(s.seed), double(s.count + int(scene.balls.size())), double(scene.balls.size())});
    return v;
}

/// Whether `n` is one of the scene's numbers, or its reciprocal ("60" frames
/// a second for dt = 1/60 s), to the digits the text gives.
bool inScene(const TextNumber& n, const std::vector<double>& values)
{
    for (const double x : values) {
        for (const double y : {std::abs(x), x != 0.0 ? 1.0 / std::abs(x) : 0.0}) {
            const double tol = std::max(n.halfUlp, 1e-9 * y);
            if (std::abs(std::abs(n.value) - y) <= tol)
                return true;
        }
    }
    return false;
}

struct Field {
    QString path;
    QString plain; ///< line breaks between paragraphs
    QString flat;  ///< the same with spaces for line breaks: what quotes are found in
    std::vector<Span> sentences;
};

std::vector<Field> fieldsOf(const Lesson& lesson)
{
    std::vector<Field> fields;
    auto add = [&](const QString& path, const QString& markup) {
        Field f;
        f.path = path;
        f.plain = plainOf(markup);
        f.flat = f.plain;
        f.flat.replace(QLatin1Char('\n'), QLatin1Char(' '));
        f.sentences = sentenceSpans(f.plain);
        fields.push_back(std::move(f));
    };
    auto addList = [&](const QString& path, const QStringList& list) {
        for (qsizetype i = 0; i < list.size(); ++i)
            add(path + QLatin1Char('.') + QString::number(i), list[i]);
    };
    add(QStringLiteral("text"), lesson.text);
    addList(QStringLiteral("challenges"), lesson.challenges);
    for (std::size_t k = 0; k < lesson.predict.size(); ++k) {
        const QString p = QStringLiteral("predict.%1").arg(k);
        add(p + QStringLiteral(".ask"), lesson.predict[k].ask);
        addList(p + QStringLiteral(".choices"), lesson.predict[k].choices);
    }
    add(QStringLiteral("teacher.goal"), lesson.teacher.goal);
    addList(QStringLiteral("teacher.misconceptions"), lesson.teacher.misconceptions);
    addList(QStringLiteral("teacher.answers"), lesson.teacher.answers);
    return fields;
}

/// A quote's pieces: split at "…" or "...", without markup or extra space.
QStringList piecesOf(const QString& says)
{
    QString flat = plainOf(says);
    flat.replace(QLatin1Char('\n'), QLatin1Char(' '));
    static const QRegularExpression ellipsis(QStringLiteral("…|\\.\\.\\."));
    QStringList pieces;
    for (const QString& piece : flat.split(ellipsis)) {
        const QString t = piece.trimmed();
        if (!t.isEmpty())
            pieces << t;
    }
    return pieces;
}

bool isWordChar(QChar c)
{
    return c.isLetterOrNumber() || c == QLatin1Char('_');
}

/// The first place from `from` where `piece` stands as whole words: "s" is
/// not found in "fast".
qsizetype findWords(const QString& text, const QString& piece, qsizetype from)
{
    for (qsizetype at = text.indexOf(piece, from, Qt::CaseInsensitive); at >= 0;
         at = text.indexOf(piece, at + 1, Qt::CaseInsensitive)) {
        const qsizetype end = at + piece.size();
        const bool startOk = at == 0 || !isWordChar(piece.front()) || !isWordChar(text[at - 1]);
        const bool endOk = end == text.size() || !isWordChar(piece.back()) || !isWordChar(text[end]);
        if (startOk && endOk)
            return at;
    }
    return -1;
}

/// Where a quote's pieces are, in order, in one field.
std::optional<std::vector<Span>> locate(const QStringList& pieces, const Field& f)
{
    std::vector<Span> spans;
    qsizetype from = 0;
    for (const QString& piece : pieces) {
        const qsizetype at = findWords(f.flat, piece, from);
        if (at < 0)
            return std::nullopt;
        spans.emplace_back(at, at + piece.size());
        from = at + piece.size();
    }
    return spans;
}

QString shortQuote(const QString& s)
{
    constexpr qsizetype kMost = 70;
    return QStringLiteral("\"%1\"").arg(s.size() <= kMost ? s : s.left(kMost - 1) + QStringLiteral("…"));
}

} // namespace

std::vector<double> numberValues(const QString& plainText, const QString& language)
{
    std::vector<double> out;
    for (const TextNumber& n : numbersIn(plainText, language))
        out.push_back(n.value);
    return out;
}

QString numberOrComparison(const QString& sentence, const QString& language)
{
    const auto n = numberPattern(language).match(sentence);
    // The words that compare are English; in a translation only its numbers
    // (the same as the English's, lesson_languages.h) call for a backing.
    const auto w = language.startsWith(QStringLiteral("en")) ? wordPattern().match(sentence) : QRegularExpressionMatch();
    if (n.hasMatch() && (!w.hasMatch() || n.capturedStart() <= w.capturedStart()))
        return n.captured(0);
    return w.hasMatch() ? w.captured(0) : QString();
}

QStringList splitSentences(const QString& text)
{
    const QString p = plainOf(text);
    QStringList out;
    for (const auto& [b, e] : sentenceSpans(p))
        out << p.mid(b, e - b);
    return out;
}

QString fieldLabel(const QString& field)
{
    const QStringList parts = field.split(QLatin1Char('.'));
    auto nth = [&](int i) { return QString::number(parts.value(i).toInt() + 1); };
    if (parts.value(0) == QLatin1String("challenges"))
        return QStringLiteral("challenge ") + nth(1);
    if (parts.value(0) == QLatin1String("predict"))
        return parts.value(2) == QLatin1String("ask") ? QStringLiteral("question ") + nth(1)
                                                      : QStringLiteral("question %1, choice %2").arg(nth(1), nth(3));
    if (parts.value(1) == QLatin1String("answers"))
        return QStringLiteral("answer ") + nth(2);
    if (parts.value(1) == QLatin1String("misconceptions"))
        return QStringLiteral("misconception ") + nth(2);
    if (parts.value(1) == QLatin1String("goal"))
        return QStringLiteral("goal");
    return field;
}

SentenceReport checkSentences(const Lesson& lesson)
{
    SentenceReport report;
    const std::vector<Field> fields = fieldsOf(lesson);
    // Per field, per sentence: the claims and entries that back it.
    std::vector<std::vector<LessonSentence>> table(fields.size());
    for (std::size_t f = 0; f < fields.size(); ++f)
        for (const auto& [b, e] : fields[f].sentences) {
            LessonSentence s;
            s.field = fields[f].path;
            s.text = fields[f].plain.mid(b, e - b);
            s.trigger = numberOrComparison(s.text, lesson.language);
            table[f].push_back(std::move(s));
        }

    // Marks the sentences a quote lies in; false when it is in no field.
    auto mark = [&](const QString& says, const QString& path, int index, bool claim) {
        const QStringList pieces = piecesOf(says);
        bool found = false;
        for (std::size_t f = 0; f < fields.size() && !pieces.isEmpty(); ++f) {
            const auto spans = locate(pieces, fields[f]);
            if (!spans)
                continue;
            found = true;
            std::vector<std::size_t> touched;
            for (std::size_t k = 0; k < fields[f].sentences.size(); ++k) {
                const auto [b, e] = fields[f].sentences[k];
                for (const auto& [sb, se] : *spans)
                    if (sb < e && se > b) {
                        touched.push_back(k);
                        break;
                    }
            }
            if (!claim && touched.size() > 1)
                report.problems << QStringLiteral("%1: %2 runs over %3 sentences of %4; list each sentence on its own")
                                       .arg(path, shortQuote(says))
                                       .arg(touched.size())
                                       .arg(fieldLabel(fields[f].path));
            for (const std::size_t k : touched)
                (claim ? table[f][k].claims : table[f][k].notMeasured).push_back(index);
        }
        if (!found)
            report.problems << QStringLiteral("%1: %2 is not in the lesson's text, challenges, questions or teacher "
                                              "notes (quote it as written; join pieces with …)")
                                   .arg(path, shortQuote(says));
    };
    for (std::size_t k = 0; k < lesson.claims.size(); ++k)
        mark(QString::fromStdString(lesson.claims[k].text), QStringLiteral("claims.%1.says").arg(k), int(k), true);
    for (std::size_t k = 0; k < lesson.notMeasured.size(); ++k)
        mark(lesson.notMeasured[k].says, QStringLiteral("not_measured.%1.says").arg(k), int(k), false);

    const std::vector<double> values = sceneNumbers(lesson.scene);
    for (std::size_t f = 0; f < fields.size(); ++f)
        for (LessonSentence& s : table[f]) {
            if (!s.trigger.isEmpty() && s.claims.empty() && s.notMeasured.empty())
                report.problems << QStringLiteral("%1: %2 says %3, but no claim checks it and not_measured does not "
                                                  "list it")
                                       .arg(s.field, shortQuote(s.text), shortQuote(s.trigger));
            for (const int k : s.notMeasured) {
                if (lesson.notMeasured[std::size_t(k)].because != NotMeasured::Because::Setting)
                    continue;
                for (const TextNumber& n : numbersIn(s.text, lesson.language))
                    if (!inScene(n, values)) {
                        report.problems << QStringLiteral("not_measured.%1: %2 is called a setting, but %3 is not a "
                                                          "number the scene sets")
                                               .arg(k)
                                               .arg(shortQuote(s.text))
                                               .arg(QString::number(n.value, 'g', 10));
                        break;
                    }
            }
            report.sentences.push_back(std::move(s));
        }
    return report;
}

} // namespace forcelab::lessons
