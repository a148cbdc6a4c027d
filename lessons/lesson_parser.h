#pragma once
// A lesson file's JSON object to a Lesson. Every problem found is collected
// with the key path it belongs to; the loader adds the source in front.

#include "lesson.h"

#include <QJsonObject>
#include <QList>
#include <QString>

namespace forcelab::lessons {

/// One problem: the key path ("models.wind.mode", "balls.3.r") and what is wrong.
struct KeyProblem {
    QString keyPath;
    QString problem;
};

struct ParseResult {
    Lesson lesson;              ///< meaningful only when `problems` is empty
    QList<KeyProblem> problems; ///< at most kMaxErrors of them
    int unlisted = 0;           ///< further problems beyond kMaxErrors
};

/// Names accepted in "overlays" (drawn by the workbench's canvas).
const QStringList& overlayNames();

/// Reads a format-1 lesson object. Absent keys keep the defaults of the
/// sim structs; a model absent from "models" is off.
ParseResult parseLesson(const QJsonObject& root);

} // namespace forcelab::lessons
