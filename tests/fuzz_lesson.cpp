// libFuzzer target for everything a lesson file or a `--set` can feed the
// loader and the lesson pane. The first byte, modulo 3, picks what the rest is:
//   0: a whole lesson file; when it loads, its saved form must load too and
//      give the same settings (a writer bug is a crash here), and its
//      sentences are checked as `forcelab-cli check` does;
//   1: the text of a `--set KEY.PATH=VALUE` applied to a small lesson;
//   2: a lesson's words, shown by the workbench's lesson pane (offscreen)
//      when the markup subset allows them, and split into sentences.
// Any crash, sanitizer report, leak or hang fails the run.

#include "lessons/lesson_loader.h"
#include "lessons/lesson_markup.h"
#include "lessons/lesson_languages.h"
#include "lessons/sentence_check.h"
#include "ui/docks/lesson_text_view.h"

#include <QApplication>

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace forcelab;

namespace {

const QByteArray kBase = R"({"format": 1, "id": "fuzz", "title": "Fuzz", "stage": 1, "text": "", "challenges": [],
  "world": {"width": 200, "height": 100, "walls": ["left", "right", "top", "bottom"]},
  "time": {"integrator": "verlet", "dt": 0.01},
  "models": {"gravity": {"x": 0, "y": 980}},
  "balls": [{"x": 50, "y": 50, "vx": 10, "vy": 0, "r": 5}],
  "controls": [], "overlays": []})";

void checkRoundTrip(const Lesson& lesson)
{
    const QByteArray saved = saveLesson(lesson);
    const LoadResult again = LessonLoader::loadBytes(saved, QStringLiteral("saved"));
    if (!again.ok())
        std::abort(); // saveLesson wrote something the loader refuses
    if (std::memcmp(&again.lesson->scene.settings.time.dt, &lesson.scene.settings.time.dt, sizeof(double)) != 0 ||
        again.lesson->scene.balls.size() != lesson.scene.balls.size())
        std::abort(); // the round trip changed the lesson
}

/// The lesson pane as the workbench shows a lesson's words: only text the
/// loader would accept reaches it. No picture exists in the folder given,
/// so every <img> must be refused by name without touching the disk.
void showInPane(const QString& text)
{
    static int argc = 1;
    static char name[] = "fuzz_lesson";
    static char* argv[] = {name, nullptr};
    static QApplication app(argc, argv);
    static LessonTextView pane;
    for (const QString& sentence : lessons::splitSentences(text))
        (void)lessons::numberOrComparison(sentence);
    if (lessons::checkMarkup(text, lessons::kMaxTextChars))
        return; // the loader refuses it; the pane never sees it
    const lessons::MarkupHtml html = lessons::markupToHtml(text);
    pane.showLesson(html.html, html.images, QStringLiteral("/nonexistent-lesson-folder"));
    pane.resize(400, 300);
    (void)pane.grab(); // lay it out and paint it
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray rest(reinterpret_cast<const char*>(data + 1), static_cast<qsizetype>(size - 1));
    if (data[0] % 3 == 0) {
        const LoadResult r = LessonLoader::loadBytes(rest, QStringLiteral("fuzz.json"));
        if (r.ok()) {
            checkRoundTrip(*r.lesson);
            (void)lessons::checkSentences(*r.lesson);
            for (const QString& code : r.lesson->languages.keys()) // each translation shown and checked
                (void)lessons::checkSentences(lessons::shownIn(*r.lesson, code));
        } else if (r.errors().isEmpty()) {
            std::abort(); // a refusal must say why
        }
        return 0;
    }
    if (data[0] % 3 == 2) {
        showInPane(QString::fromUtf8(rest));
        return 0;
    }
    QString error;
    const auto override = LessonLoader::parseOverride(QString::fromUtf8(rest), &error);
    if (!override) {
        if (error.isEmpty())
            std::abort();
        return 0;
    }
    const LoadResult r = LessonLoader::loadBytes(kBase, QStringLiteral("base.json"), {*override});
    if (r.ok())
        checkRoundTrip(*r.lesson);
    else if (r.errors().isEmpty())
        std::abort();
    return 0;
}
