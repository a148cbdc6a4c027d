#pragma once
// Lesson files (JSON, format 1) to plain sim structs, with one-line errors that
// name the source and the key path. Built-in lessons are compiled in as Qt
// resources under ":/lessons/".

#include "lesson.h"
#include "sim/world/error.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace forcelab {

/// `--set KEY.PATH=VALUE`: replaces one value of the lesson before it is parsed.
struct Override {
    QString keyPath; ///< e.g. "models.gravity.y" or "time.integrator"
    QString value;   ///< JSON text ("0", "\"rk4\"", "true") or a bare word taken as a string ("rk4")
};

struct LoadResult {
    std::optional<Lesson> lesson;  ///< set when there was no error
    QList<sim::Error> problems;    ///< what is wrong: source, key path, line and column (in a file), message
    /// The problems as the lines a user reads ("file:line:column: key.path: what").
    QStringList errors() const;
    bool ok() const { return lesson.has_value(); }
};

/// The line a user reads for a problem (sim::toString, as a QString).
QString errorLine(const sim::Error& error);

class LessonLoader {
public:
    /// A path on disk, or a built-in lesson's id ("gravity") or file stem ("07-gravity").
    static LoadResult load(const QString& pathOrId, const QList<Override>& overrides = {});
    static LoadResult loadFile(const QString& path, const QList<Override>& overrides = {});
    static LoadResult loadBytes(const QByteArray& json, const QString& source, const QList<Override>& overrides = {});

    /// Resource paths of the built-in lessons, sorted by file name (":/lessons/00-showcase.json", …).
    static QStringList builtInFiles();

    /// Names accepted in a lesson's "overlays": grid, velocity, acceleration, readout, colliding, markers.
    static QStringList overlayNames();
    /// Names accepted in a lesson's "controls": gravity, drag, wind, …, integrator, dt (docs/lessons.md).
    static QStringList controlNames();

    /// Parses "KEY.PATH=VALUE"; on failure returns nullopt and sets *error.
    static std::optional<Override> parseOverride(const QString& text, QString* error);
};

/// The lesson as a format-1 JSON document that loads back to the same lesson.
QByteArray saveLesson(const Lesson& lesson);

} // namespace forcelab
