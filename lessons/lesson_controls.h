#pragma once
// The names a lesson may list in "controls", and which rows of the
// Parameters panel each one shows. The lesson reader checks names against
// this table and the panel lays out its rows from it, so a control name is
// defined once. A row is a parameter's `control` (sim/world/parameters.cpp) or one
// of the panel's own rows (wall_sides, seed, ball_count, fully_inside,
// time_scale).

#include <QHash>
#include <QString>
#include <QStringList>

namespace forcelab::lessons {

/// Control name → the panel rows it shows.
const QHash<QString, QStringList>& controlRows();

/// Every control name, sorted (for messages and validation).
const QStringList& controlNames();

} // namespace forcelab::lessons
