#include "lesson_languages.h"

#include "lesson_markup.h"
#include "sentence_check.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <functional>

namespace forcelab::lessons {

namespace {

void applyWords(Lesson& lesson, const LessonWords& w)
{
    lesson.title = w.title;
    lesson.text = w.text;
    lesson.challenges = w.challenges;
    for (std::size_t k = 0; k < lesson.predict.size(); ++k) {
        lesson.predict[k].ask = w.predictAsks.value(qsizetype(k));
        if (k < w.predictChoices.size())
            lesson.predict[k].choices = w.predictChoices[k];
    }
    lesson.teacher.goal = w.goal;
    lesson.teacher.misconceptions = w.misconceptions;
    lesson.teacher.answers = w.answers;
    for (std::size_t k = 0; k < lesson.claims.size(); ++k)
        lesson.claims[k].text = w.claims.value(qsizetype(k)).toStdString();
    for (std::size_t k = 0; k < lesson.notMeasured.size(); ++k) {
        lesson.notMeasured[k].says = w.notMeasuredSays.value(qsizetype(k));
        lesson.notMeasured[k].why = w.notMeasuredWhy.value(qsizetype(k));
    }
    for (std::size_t k = 0; k < lesson.compare.size(); ++k)
        lesson.compare[k].label = w.compare.value(qsizetype(k));
}

/// Each field of two sets of words side by side, by its path.
void eachPair(const LessonWords& a, const LessonWords& b,
              const std::function<void(const QString&, const QString&, const QString&)>& f)
{
    f(QStringLiteral("title"), a.title, b.title);
    f(QStringLiteral("text"), a.text, b.text);
    auto list = [&](const QString& path, const QStringList& x, const QStringList& y) {
        for (qsizetype i = 0; i < std::min(x.size(), y.size()); ++i)
            f(path + QLatin1Char('.') + QString::number(i), x[i], y[i]);
    };
    list(QStringLiteral("challenges"), a.challenges, b.challenges);
    for (qsizetype k = 0; k < std::min(a.predictAsks.size(), b.predictAsks.size()); ++k) {
        const QString p = QStringLiteral("predict.%1").arg(k);
        f(p + QStringLiteral(".ask"), a.predictAsks[k], b.predictAsks[k]);
        if (std::size_t(k) < a.predictChoices.size() && std::size_t(k) < b.predictChoices.size())
            list(p + QStringLiteral(".choices"), a.predictChoices[std::size_t(k)], b.predictChoices[std::size_t(k)]);
    }
    f(QStringLiteral("teacher.goal"), a.goal, b.goal);
    list(QStringLiteral("teacher.misconceptions"), a.misconceptions, b.misconceptions);
    list(QStringLiteral("teacher.answers"), a.answers, b.answers);
    list(QStringLiteral("claims"), a.claims, b.claims);
    for (qsizetype k = 0; k < std::min(a.notMeasuredSays.size(), b.notMeasuredSays.size()); ++k) {
        const QString p = QStringLiteral("not_measured.%1").arg(k);
        f(p + QStringLiteral(".says"), a.notMeasuredSays[k], b.notMeasuredSays[k]);
        f(p + QStringLiteral(".why"), a.notMeasuredWhy.value(k), b.notMeasuredWhy.value(k));
    }
    list(QStringLiteral("compare"), a.compare, b.compare);
}

QString numbersText(const std::vector<double>& v)
{
    QStringList parts;
    for (const double x : v)
        parts << QString::number(x, 'g', 12);
    return parts.isEmpty() ? QStringLiteral("none") : parts.join(QStringLiteral(", "));
}

} // namespace

bool isLanguageCode(const QString& code)
{
    static const QRegularExpression pattern(QStringLiteral("^[a-z]{2,3}(-[A-Z]{2})?$"));
    return pattern.match(code).hasMatch();
}

LessonWords wordsOf(const Lesson& lesson)
{
    LessonWords w;
    w.title = lesson.title;
    w.text = lesson.text;
    w.challenges = lesson.challenges;
    for (const Prediction& q : lesson.predict) {
        w.predictAsks << q.ask;
        w.predictChoices.push_back(q.choices);
    }
    w.goal = lesson.teacher.goal;
    w.misconceptions = lesson.teacher.misconceptions;
    w.answers = lesson.teacher.answers;
    for (const sim::Claim& c : lesson.claims)
        w.claims << QString::fromStdString(c.text);
    for (const NotMeasured& n : lesson.notMeasured) {
        w.notMeasuredSays << n.says;
        w.notMeasuredWhy << n.why;
    }
    for (const ComparePane& p : lesson.compare)
        w.compare << p.label;
    return w;
}

bool showIn(Lesson& lesson, const QString& code)
{
    if (code == lesson.language)
        return true;
    const auto it = lesson.languages.constFind(code);
    if (it == lesson.languages.cend())
        return false;
    const LessonWords shown = *it;
    lesson.languages.remove(code);
    lesson.languages.insert(lesson.language, wordsOf(lesson));
    applyWords(lesson, shown);
    lesson.language = code;
    return true;
}

Lesson shownIn(const Lesson& lesson, const QString& code)
{
    Lesson out = lesson;
    if (!showIn(out, code))
        showIn(out, out.fileLanguage);
    return out;
}

QStringList shapeProblems(const Lesson& lesson, const LessonWords& w, const QString& path)
{
    QStringList problems;
    auto count = [&](const QString& field, qsizetype got, qsizetype want) {
        if (got != want)
            problems << QStringLiteral("%1.%2: %3 %4; the lesson has %5")
                            .arg(path, field)
                            .arg(got)
                            .arg(got == 1 ? QStringLiteral("entry") : QStringLiteral("entries"))
                            .arg(want);
    };
    auto present = [&](const QString& field, const QString& got, const QString& want) {
        if (got.isEmpty() != want.isEmpty())
            problems << (got.isEmpty() ? QStringLiteral("%1.%2: missing; the lesson has one").arg(path, field)
                                       : QStringLiteral("%1.%2: the lesson has none; leave it out").arg(path, field));
    };
    present(QStringLiteral("title"), w.title, lesson.title);
    present(QStringLiteral("text"), w.text, lesson.text);
    count(QStringLiteral("challenges"), w.challenges.size(), lesson.challenges.size());
    count(QStringLiteral("predict"), w.predictAsks.size(), qsizetype(lesson.predict.size()));
    for (std::size_t k = 0; k < std::min(lesson.predict.size(), w.predictChoices.size()); ++k)
        count(QStringLiteral("predict.%1.choices").arg(k), w.predictChoices[k].size(), lesson.predict[k].choices.size());
    present(QStringLiteral("teacher.goal"), w.goal, lesson.teacher.goal);
    count(QStringLiteral("teacher.misconceptions"), w.misconceptions.size(), lesson.teacher.misconceptions.size());
    count(QStringLiteral("teacher.answers"), w.answers.size(), lesson.teacher.answers.size());
    count(QStringLiteral("claims"), w.claims.size(), qsizetype(lesson.claims.size()));
    count(QStringLiteral("not_measured"), w.notMeasuredSays.size(), qsizetype(lesson.notMeasured.size()));
    for (std::size_t k = 0; k < std::min(lesson.notMeasured.size(), std::size_t(w.notMeasuredWhy.size())); ++k)
        present(QStringLiteral("not_measured.%1.why").arg(k), w.notMeasuredWhy[qsizetype(k)], lesson.notMeasured[k].why);
    count(QStringLiteral("compare"), w.compare.size(), qsizetype(lesson.compare.size()));
    return problems;
}

std::vector<double> numbersOf(const QString& plainText, const QString& language)
{
    // Read as the sentence check reads them, rounded so that the same value
    // written two ways (0.8, 0,8) compares equal.
    std::vector<double> out = numberValues(plainText, language);
    for (double& v : out)
        v = std::round(v * 1e12) / 1e12;
    std::sort(out.begin(), out.end());
    return out;
}

QStringList numberProblems(const LessonWords& own, const QString& ownLanguage, const LessonWords& translation,
                           const QString& code)
{
    QStringList problems;
    eachPair(own, translation, [&](const QString& path, const QString& a, const QString& b) {
        const std::vector<double> na = numbersOf(markupToPlainText(a), ownLanguage);
        const std::vector<double> nb = numbersOf(markupToPlainText(b), code);
        if (na != nb)
            problems << QStringLiteral("languages.%1.%2: numbers %3 where the lesson has %4")
                            .arg(code, path, numbersText(nb), numbersText(na));
    });
    return problems;
}

} // namespace forcelab::lessons
