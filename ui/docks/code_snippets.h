#pragma once
// The code behind a stage: regions of the simulation's own sources, marked
//     // [code NAME if KEY=VALUE: Title]   …   // [/code]
// with single lines marked "// [if KEY=VALUE]" at their end. The sources are
// compiled into the program from sim/ in the same build, so what the Code
// panel shows is the code that runs. KEY is a parameter key path
// (sim/world/parameters.h) and VALUE a choice name, true/false or a number.

#include "sim/world/world_settings.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace forcelab {

/// A condition on one setting: "time.integrator=euler".
struct SettingTest {
    QString key;   ///< parameter key path
    QString value; ///< as written
    /// Whether `settings` has that value; false for an unknown key or value.
    bool holds(const sim::WorldSettings& settings) const;
    bool valid() const; ///< the key is a parameter and the value one it can take
};

struct CodeLine {
    int number = 0;    ///< 1-based line in the source file
    QString text;      ///< as in the file, without a trailing "// [if …]"
    SettingTest test;  ///< empty key: the line has no condition
};

struct CodeRegion {
    QString name;      ///< "step.euler", "walls.test", …
    QString title;     ///< "One step of explicit Euler"
    QString file;      ///< path under sim/, e.g. "integrators/integrators.cpp"
    SettingTest test;  ///< when this is the code that runs
    QList<CodeLine> lines;
    /// The keys this region's code depends on (its own and its lines').
    QStringList keys() const;
};

/// The regions of one source text; problems (an unclosed region, a marker
/// that does not parse) are added to `problems` as "file:line: what".
QList<CodeRegion> parseCodeRegions(const QString& text, const QString& file, QStringList* problems = nullptr);

/// The regions of every source compiled in (":/sim-source/…").
const QList<CodeRegion>& builtInCodeRegions();

/// The regions a lesson shows: those whose code runs with `settings`, and
/// those that depend on a parameter the lesson gives a control for
/// (`controlKeys`, parameter key paths), so a student sees both sides of a
/// switch.
QList<const CodeRegion*> regionsFor(const sim::WorldSettings& settings, const QStringList& controlKeys);

} // namespace forcelab
