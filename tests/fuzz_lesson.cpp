// libFuzzer target for everything a lesson file or a `--set` can feed the
// loader. The first byte picks what the rest is:
//   even: a whole lesson file; when it loads, its saved form must load too
//         and give the same settings (a writer bug is a crash here);
//   odd:  the text of a `--set KEY.PATH=VALUE` applied to a small lesson.
// Any crash, sanitizer report, leak or hang fails the run.

#include "lessons/lesson_loader.h"

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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray rest(reinterpret_cast<const char*>(data + 1), static_cast<qsizetype>(size - 1));
    if (data[0] % 2 == 0) {
        const LoadResult r = LessonLoader::loadBytes(rest, QStringLiteral("fuzz.json"));
        if (r.ok())
            checkRoundTrip(*r.lesson);
        else if (r.errors().isEmpty())
            std::abort(); // a refusal must say why
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
