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

/// Switches the application's font (menus, docks, dialogs) and the charts'
/// fonts below `root` between the desktop size and the projector size.
void applyProjectorFonts(QWidget* root, bool projector);

} // namespace forcelab
