#pragma once
// Small helpers shared by the subcommands' argument parsing.

#include "lessons/lesson_loader.h"
#include "sim/world/world.h"

#include <optional>
#include <ostream>
#include <string>

namespace forcelab::cli {

/// The whole text as a finite number ("12", "1e-3"); nullopt for anything
/// else: trailing characters, "nan", "inf", out of range.
std::optional<double> parseFiniteNumber(const std::string& text);

/// Loads a lesson (a file or a built-in id) with its overrides and starts
/// `world` on it. On failure writes every problem to `err`, one per line, and
/// returns nullopt (the caller exits with code 2).
std::optional<Lesson> loadLessonWorld(const QString& pathOrId, const QList<Override>& overrides, sim::World& world,
                                      std::ostream& err);

} // namespace forcelab::cli
