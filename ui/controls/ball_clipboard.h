#pragma once
// A ball on the clipboard, written as a lesson file writes a ball
// ({"x": 150, "y": 200, "vx": 40, "vy": 0, "r": 20, "mass": 33510.32, "q": 1,
// "color": "#e05050"}), so a ball copied in ForceLab can be pasted into a
// lesson file and a lesson file's ball can be pasted onto the canvas.

#include "sim/world/ball_state.h"

#include <QString>

#include <optional>

namespace forcelab {

/// The ball as one line of JSON, every number with the digits that read back exactly.
QString ballToText(const sim::Ball& ball);

/// The ball in `text` (a JSON object with at least x, y and r; vx, vy, mass,
/// q, color, pinned and restitution are optional), or nullopt with the reason in `why`. Ranges
/// are not checked here (the editor checks them); at most 4,096 characters
/// are read.
std::optional<sim::Ball> ballFromText(const QString& text, QString* why = nullptr);

} // namespace forcelab
