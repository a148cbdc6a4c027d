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

/// A phrase of a challenge that sends students to a control, and the
/// control names any one of which puts that control on the stage
/// ("the bottom wall" → walls; "the collision restitution" → restitution
/// or collisions).
struct ControlPhrase {
    QString words;       ///< the phrase as it occurred in the text
    QStringList anyOf;   ///< listing any one of these offers the control
};

/// The phrases of `plainText` that name a control none of whose names is in
/// `declared`. Only wordings that ask for a change are matched ("Set gravity
/// to", "Turn the bottom wall off", "Switch to mirror"), so a sentence that
/// merely talks about gravity passes.
QList<ControlPhrase> undeclaredControlsIn(const QString& plainText, const QStringList& declared);

} // namespace forcelab::lessons
