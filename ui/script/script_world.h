#pragma once
// A lesson's world run by its JavaScript (lessons/code/*.js) in a QJSEngine:
// the balls are a plain JS array of {x, y, vx, vy, r, m, q} objects and the
// settings a plain object, and each step() calls the script's step(world, balls).
// The script reaches nothing outside the simulation: the engine gets no
// extensions and no QObjects, so it has no files, network or console. A call
// that runs longer than the time limit (1 s) is interrupted by a watchdog and
// reported; a JS error is reported with its file, line and column.
#include "sim/forces/force_model.h"
#include "sim/world/ball_state.h"
#include "sim/world/world.h"
#include "sim/world/world_settings.h"
#include "ui/script/script_pieces.h"

#include <QJSEngine>
#include <QJSValue>
#include <QMap>
#include <QString>

#include <chrono>
#include <memory>
#include <optional>

namespace forcelab {

class ScriptWatchdog;

struct ScriptError {
    QString message;   ///< as the engine gives it ("ReferenceError: x is not defined")
    QString file;      ///< the piece ("walls.js") or the name given to evaluate()
    int line = 0;      ///< 1-based, 0 when unknown
    int column = 0;    ///< 1-based, 0 when the engine does not say (Qt 6.4 says it for syntax errors only)
    /// "walls.js:12:5: ReferenceError: …"
    QString text() const;
};

struct ScriptBall {
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0; ///< px, px/s
    double r = 0.0, m = 0.0;                     ///< px, mass
};

class ScriptWorld {
public:
    ScriptWorld();
    ~ScriptWorld();
    ScriptWorld(const ScriptWorld&) = delete;
    ScriptWorld& operator=(const ScriptWorld&) = delete;

    /// Loads the pieces of `settings` (scriptPiecesFor) and hands the script the
    /// balls. Fails on a piece's error, or when the settings need a rule no piece
    /// covers yet (ScriptPieces::missing).
    std::optional<ScriptError> load(const sim::WorldSettings& settings, const sim::BallState& balls,
                                    const sim::SpawnSettings& spawn = {});
    /// Loads these pieces and, after them, `extra` (a student's change, a test's):
    /// what extra defines replaces what the pieces did.
    std::optional<ScriptError> load(const QStringList& pieces, const sim::WorldSettings& settings,
                                    const sim::BallState& balls, const sim::SpawnSettings& spawn = {},
                                    const QString& extra = {}, const QMap<QString, QString>& replaced = {});
    /// Loads the pieces `world`'s settings need and, after them, `extra`, and
    /// goes on from where `world` is: its balls, its time, and its random
    /// generators (the random acceleration's, the wind's and spawning's) at the
    /// numbers they will draw next, so the script's next step is the engine's.
    /// A piece named in `replaced` is loaded from the text given there (a
    /// student's own version of that file) instead of the course's.
    std::optional<ScriptError> loadFrom(const sim::World& world, const QString& extra = {},
                                        const QMap<QString, QString>& replaced = {});
    /// The pieces loadFrom uses for `world`, or the error naming what no piece covers.
    static std::optional<ScriptError> piecesFor(const sim::World& world, QStringList& files);

    /// One step: the script's step(world, balls).
    std::optional<ScriptError> step();
    /// Runs `code` under the watchdog, as file `file`.
    std::optional<ScriptError> evaluate(const QString& code, const QString& file);

    /// Where the pointer is (world.pointer in the script; null while it is outside).
    void setPointer(const sim::PointerInput& pointer);

    int ballCount() const;
    ScriptBall ball(int i) const;
    /// The script's own value of global `name` (a function, a list it keeps).
    QJSValue global(const QString& name) const;
    /// The `world` object the script steps.
    QJSValue worldObject() const { return m_world; }
    QJSValue ballsObject() const { return m_balls; }
    QJSEngine& engine() { return m_engine; }
    void setTimeLimit(std::chrono::milliseconds limit) { m_limit = limit; }

private:
    std::optional<ScriptError> errorOf(const QJSValue& result, const QString& file, bool interrupted) const;
    QJSValue settingsObject(const sim::WorldSettings& s, const sim::SpawnSettings& spawn);
    QJSValue ballsArray(const sim::BallState& balls);

    QJSEngine m_engine;
    std::unique_ptr<ScriptWatchdog> m_watchdog;
    std::chrono::milliseconds m_limit{1000};
    QJSValue m_world;
    QJSValue m_balls;
    QJSValue m_step;
};

} // namespace forcelab
