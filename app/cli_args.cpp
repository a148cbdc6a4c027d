#include "cli_args.h"
#include "cli_commands.h"

#include "lessons/message_text.h"

#include <cmath>
#include <stdexcept>

namespace forcelab::cli {

std::string echo(const std::string& value)
{
    return lessons::cutForMessage(QString::fromStdString(value)).toStdString();
}

std::optional<double> parseFiniteNumber(const std::string& text)
{
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(v))
            return std::nullopt;
        return v;
    } catch (const std::logic_error&) { // invalid_argument, out_of_range
        return std::nullopt;
    }
}

std::optional<Lesson> loadLessonWorld(const QString& pathOrId, const QList<Override>& overrides, sim::World& world,
                                      std::ostream& err)
{
    LoadResult loaded = LessonLoader::load(pathOrId, overrides);
    if (!loaded.ok()) {
        for (const QString& e : loaded.errors())
            err << e.toStdString() << "\n";
        return std::nullopt;
    }
    if (auto error = world.reset(loaded.lesson->scene)) {
        sim::Error e = *error;
        e.source = loaded.lesson->source.toStdString();
        err << sim::toString(e) << "\n";
        return std::nullopt;
    }
    return std::move(loaded.lesson);
}

} // namespace forcelab::cli
