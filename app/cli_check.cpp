// forcelab-cli check [LESSON...]: runs the claims of lessons (every built-in
// lesson when none is named) and reports each one.

#include "cli_commands.h"

#include "lessons/lesson_languages.h"
#include "lessons/lesson_loader.h"
#include "lessons/sentence_check.h"

#include <algorithm>

#include <QFileInfo>

namespace forcelab::cli {

namespace {

// A table cell: one line, no column breaks.
std::string cell(std::string text)
{
    for (char& c : text)
        if (c == '\n')
            c = ' ';
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += '\\';
        out += c;
    }
    return out;
}

} // namespace

void declareCheck(QCommandLineParser& p)
{
    p.addOption(QCommandLineOption(QStringLiteral("markdown"),
                                   QStringLiteral("Print the claims as Markdown tables, one per lesson (docs/lessons.md "
                                                  "holds this list; a test compares the two).")));
    p.addPositionalArgument(QStringLiteral("lessons"), QStringLiteral("Lesson files or built-in ids (default: all built-in)."),
                            QStringLiteral("[LESSON...]"));
}

namespace {

/// The Markdown of one lesson: its claims with the sentences they back, then
/// the sentences with numbers that are not claims and why.
void lessonMarkdown(std::ostream& out, const std::string& label, const Lesson& lesson,
                    const std::vector<sim::ClaimResult>& results, const lessons::SentenceReport& report)
{
    if (lesson.claims.empty() && lesson.notMeasured.empty())
        return;
    out << "\n### " << label << ": " << lesson.title.toStdString() << "\n";
    // Where a quote is, and the sentences it lies in (those of its first field).
    auto backed = [&](int k, bool claim) {
        QStringList where, sentences;
        QString first;
        for (const lessons::LessonSentence& s : report.sentences) {
            const auto& list = claim ? s.claims : s.notMeasured;
            if (std::find(list.begin(), list.end(), k) == list.end())
                continue;
            const QString label = lessons::fieldLabel(s.field);
            if (!where.contains(label))
                where << label;
            if (first.isEmpty())
                first = s.field;
            if (s.field == first)
                sentences << s.text;
        }
        return std::pair{where.join(QStringLiteral(", ")).toStdString(), sentences.join(QLatin1Char(' ')).toStdString()};
    };
    if (!lesson.claims.empty()) {
        out << "\n| where | the lesson says | measurement | result |\n|---|---|---|---|\n";
        for (std::size_t k = 0; k < lesson.claims.size(); ++k) {
            const sim::Claim& claim = lesson.claims[k];
            const auto [where, sentence] = backed(int(k), true);
            const std::string what = claim.measure + (claim.set.empty() ? "" : " (with its own settings)");
            out << "| " << cell(where) << " | " << cell(sentence.empty() ? claim.text : sentence) << " | " << cell(what)
                << " | " << (results[k].holds ? "holds: " : "FAILS: ") << cell(results[k].explanation) << " |\n";
        }
    }
    if (!lesson.notMeasured.empty()) {
        out << "\nNot claims:\n\n| where | the lesson says | why it is not a claim |\n|---|---|---|\n";
        for (std::size_t k = 0; k < lesson.notMeasured.size(); ++k) {
            const NotMeasured& n = lesson.notMeasured[k];
            const auto [where, sentence] = backed(int(k), false);
            std::string why = kNotMeasuredReasons[int(n.because)];
            if (!n.why.isEmpty())
                why += ": " + n.why.toStdString();
            out << "| " << cell(where) << " | " << cell(sentence.empty() ? n.says.toStdString() : sentence) << " | "
                << cell(why) << " |\n";
        }
    }
}

} // namespace

int checkCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    QStringList lessons = parser.positionalArguments();
    if (lessons.isEmpty())
        lessons = LessonLoader::builtInFiles();
    const bool markdown = parser.isSet(QStringLiteral("markdown"));
    int claims = 0, failed = 0, withClaims = 0, statements = 0, byClaims = 0, unbacked = 0, translations = 0;
    for (const QString& name : lessons) {
        const LoadResult r = LessonLoader::load(name);
        if (!r.ok()) {
            for (const QString& line : r.errors())
                err << line.toStdString() << "\n";
            return 2;
        }
        const Lesson& lesson = *r.lesson;
        const std::string label = QFileInfo(lesson.source).completeBaseName().toStdString();
        withClaims += lesson.claims.empty() ? 0 : 1;
        std::vector<sim::ClaimResult> results;
        for (const sim::Claim& claim : lesson.claims) {
            results.push_back(sim::checkClaim(lesson.scene, claim));
            ++claims;
            failed += results.back().holds ? 0 : 1;
            if (!markdown)
                out << label << ": " << sim::describe(claim, results.back()) << "\n";
        }
        const lessons::SentenceReport report = lessons::checkSentences(lesson);
        for (const lessons::LessonSentence& s : report.sentences)
            if (!s.trigger.isEmpty()) {
                ++statements;
                byClaims += s.claims.empty() ? 0 : 1;
            }
        unbacked += int(report.problems.size());
        for (const QString& problem : report.problems)
            (markdown ? err : out) << label << ": " << problem.toStdString() << "\n";
        if (markdown)
            lessonMarkdown(out, label, lesson, results, report);
        // Each translation's sentences are backed by its own quotes of the
        // same claims (its numbers are the lesson's: the loader checks that).
        for (const QString& code : lesson.languages.keys()) {
            ++translations;
            const lessons::SentenceReport translated = lessons::checkSentences(lessons::shownIn(lesson, code));
            unbacked += int(translated.problems.size());
            for (const QString& problem : translated.problems)
                (markdown ? err : out) << label << " [" << code.toStdString() << "]: " << problem.toStdString() << "\n";
        }
    }
    if (markdown)
        out << "\n";
    out << claims << (claims == 1 ? " claim" : " claims") << " in " << withClaims << " of " << lessons.size()
        << (lessons.size() == 1 ? " lesson" : " lessons") << ": ";
    if (failed == 0)
        out << (claims == 1 ? "it holds" : "all hold");
    else
        out << failed << " of them " << (failed == 1 ? "does" : "do") << " not hold";
    out << "; " << statements << (statements == 1 ? " sentence" : " sentences") << " with numbers or comparisons, "
        << byClaims << " backed by claims, " << statements - byClaims << " listed as not claims";
    if (translations > 0)
        out << "; the same in " << translations << (translations == 1 ? " translation" : " translations");
    if (unbacked > 0)
        out << "; " << unbacked << (unbacked == 1 ? " problem" : " problems") << " with the sentences (listed above)";
    out << "\n";
    return failed == 0 && unbacked == 0 ? 0 : 1;
}

} // namespace forcelab::cli
