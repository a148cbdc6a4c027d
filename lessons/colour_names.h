#pragma once
// The colour names a lesson may use, in its "color" fields and in its text,
// and the one colour drawn for each in both themes. The projector theme keeps
// a listed colour exactly (ui/drawing/palette.h), so "the red ball" of a text
// is red on every screen and projector; the colours are the Okabe–Ito palette
// where it has a colour a class calls by that name (its reddish purple is the
// pink), and a red, a purple, a grey and a white where it has none: its
// vermillion reads orange, so it is not listed.

#include "sim/world/types.h"

#include <QString>
#include <QStringList>

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace forcelab::lessons {

struct ColourName {
    /// The words a text or a "color" field may use for it, the first one the
    /// name the writer saves; lower case, at most three.
    std::array<std::string_view, 3> words;
    sim::Rgb color; ///< 0xrrggbb, drawn as it is in the plain and the projector theme
};

/// Every listed colour. Names of two words ("sky blue") come before the
/// one-word names they contain ("blue"), so a text is matched longest first.
std::span<const ColourName> colourNames();

/// The colour of a listed name ("red", "Sky Blue", "gray"), or nullopt.
std::optional<sim::Rgb> colourOfName(const QString& name);

/// The first name of a listed colour ("red" for 0xe05050), or an empty string.
QString nameOfColour(sim::Rgb color);

/// True when `color` is one of the listed colours.
bool isListedColour(sim::Rgb color);

/// Every word of the list in its order ("sky blue", "light blue", "blue", …):
/// a name comes before the shorter names it contains.
QStringList colourWords();

} // namespace forcelab::lessons
