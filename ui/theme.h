#pragma once
// The projector theme: what a class at the back of a room can read. A white
// box with dark, thick outlines, larger text in every window, and ball
// colours from the Okabe–Ito palette, which stays distinguishable for the
// common kinds of colour blindness. Touching balls get a ring as well as a
// colour, so the marking does not rest on colour alone.

#include "world_painter.h"

#include "sim/types.h"

#include <array>

class QWidget;

namespace forcelab {

/// Okabe & Ito (2008), "Color Universal Design": black, orange, sky blue,
/// bluish green, yellow, blue, vermillion, reddish purple.
inline constexpr std::array<sim::Rgb, 8> kOkabeIto{0x000000, 0xe69f00, 0x56b4e9, 0x009e73,
                                                   0xf0e442, 0x0072b2, 0xd55e00, 0xcc79a7};

/// The Okabe–Ito colour nearest in hue to `color`, so "the red ball" of a
/// lesson text stays the reddest ball. White and greys stay as they are
/// (lightness needs no colour vision); very dark colours become black.
sim::Rgb okabeItoColor(sim::Rgb color);

/// The canvas colours and outlines of the plain (false) or projector (true) theme.
CanvasColors canvasColors(bool projector);

/// How much larger than the desktop's the projector theme's text is.
inline constexpr double kProjectorFontScale = 1.35;

/// Switches the application's font (menus, docks, dialogs) and the charts'
/// fonts below `root` between the desktop size and the projector size.
void applyProjectorFonts(QWidget* root, bool projector);

} // namespace forcelab
