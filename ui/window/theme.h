#pragma once
// The projector theme: what a class at the back of a room can read. A white
// box with dark, thick outlines (drawing/palette.h), larger text in every
// window, and ball colours from the Okabe–Ito palette. Touching balls get a
// ring as well as a colour, so the marking does not rest on colour alone.

#include "ui/drawing/palette.h"

class QWidget;

namespace forcelab {

/// How much larger than the desktop's the projector theme's text is.
inline constexpr double kProjectorFontScale = 1.35;

/// The text size a teacher chooses (Ctrl+= and Ctrl+−), as a factor of the
/// desktop's: from kSmallestTextScale to kLargestTextScale in steps of kTextScaleStep.
inline constexpr double kSmallestTextScale = 0.75, kLargestTextScale = 3.0, kTextScaleStep = 1.2;

/// Switches the application's font (menus, docks, dialogs, the stage bar)
/// and the charts' fonts below `root` between the desktop size and the
/// projector size, times the teacher's `textScale`.
void applyProjectorFonts(QWidget* root, bool projector, double textScale = 1.0);

} // namespace forcelab
