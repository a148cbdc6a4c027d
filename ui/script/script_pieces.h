#pragma once
// Which JavaScript files (lessons/code/*.js, compiled in under ":/lesson-code/")
// a world runs: chosen from its settings the way the Code panel's C++ regions
// are (code_snippets.h), so a lesson never lists its pieces by hand. What the
// JavaScript does not cover yet is named in `missing`, so a caller can say so
// instead of running code that would do something else.
#include "sim/world/scene.h"
#include "sim/world/world_settings.h"
#include <QString>
#include <QStringList>
namespace forcelab {
struct ScriptPieces {
    QStringList files;   ///< file names in load order ("world.js", "step_semi_implicit_euler.js", …)
    QStringList missing; ///< rules the engine runs that no piece covers yet, in words
};
/// The pieces for `settings` (and `spawn`, for balls that appear while it
/// runs), in the order they must be loaded.
ScriptPieces scriptPiecesFor(const sim::WorldSettings& settings, const sim::SpawnSettings& spawn = {});
/// The text of one piece (":/lesson-code/NAME"); empty when there is none.
QString scriptPieceSource(const QString& name);
/// Every piece compiled in, sorted by name.
QStringList allScriptPieces();
} // namespace forcelab
