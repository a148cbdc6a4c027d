#pragma once
// The sections of a lesson file, each read by its own unit of parseLesson:
// world, time and models (lesson_parse_settings.cpp), balls and spawn
// (lesson_parse_balls.cpp), claims and not_measured
// (lesson_parse_claims.cpp), predict and compare (lesson_parse_questions.cpp).

#include "lesson_reader.h"

#include "sim/studies/claims.h"
#include "sim/world/scene.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace forcelab::lessons::parsing {

/// "world": the rows of the world section, and "walls" as a list of names.
void parseWorld(Reader& r, const QJsonObject& o, sim::WorldSettings& s);
/// "time": the rows of the time section, and the seed.
void parseTime(Reader& r, const QJsonObject& o, sim::WorldSettings& s);
/// "models": one object per model, the rows of its section (the custom
/// force's formulas and constants as well).
void parseModels(Reader& r, const QJsonObject& models, sim::WorldSettings& s);

/// "units": {"px_per_metre": 100, "kg_per_mass": 1}, the scale of the
/// lesson's SI mode; a key left out keeps its default (100 px = 1 m, 1 kg).
void parseUnits(Reader& r, const QJsonObject& o, std::optional<LessonUnits>& out);

/// "balls": the listed balls, each {"x": …, "y": …, …}.
void parseBalls(Reader& r, const QJsonArray& balls, std::vector<sim::Ball>& out);
/// "spawn": the random balls; `listed` balls are in "balls".
void parseSpawn(Reader& r, const QJsonObject& o, int listed, sim::SpawnSettings& s);

/// {"key.path": value, …}: parameter rows and values allowed for them
/// (choices by name, switches as true/false), as claims' and compare panes'
/// "set". With `scene`, a claim's: its keys may also name a listed ball's
/// start or the random balls' count and ranges (sim/world/scene_keys.h), which are
/// applied to one copy of the scene, made at the first such key, so that
/// the ranges are checked as the claim will run them.
void parseSet(Reader& r, const QJsonObject& set, const QString& sp, std::vector<std::pair<std::string, double>>& out,
              const sim::Scene* scene = nullptr);
/// "claims": each a measurement of the `scene` and the value it must give.
void parseClaims(Reader& r, const QJsonArray& a, const sim::Scene& scene, std::vector<sim::Claim>& out);
/// "not_measured": sentences with numbers that are not claims, and why.
void parseNotMeasured(Reader& r, const QJsonArray& a, std::vector<NotMeasured>& out);
/// Each claim runs its scene to `at`: refused when that takes more sub-steps
/// than kMaxClaimSteps, with the claim's own dt and sub-steps where it sets them.
void checkClaimWork(Reader& r, const Lesson& lesson);

/// "predict": questions, each answered by one of `claims` claims.
void parsePredict(Reader& r, const QJsonArray& a, int claims, std::vector<Prediction>& out);
/// "compare": panes, each a label and the settings it runs with.
void parseCompare(Reader& r, const QJsonArray& a, std::vector<ComparePane>& out);

} // namespace forcelab::lessons::parsing
