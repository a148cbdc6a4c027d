#pragma once
// The canvas's colours: the Okabe–Ito palette, which stays distinguishable
// for the common kinds of colour blindness, and the plain and projector
// themes' canvas colours. Drawing only (QtGui), so the command line draws
// as the workbench does.

#include "world_painter.h"

#include "sim/world/types.h"

#include <array>

namespace forcelab {

/// Okabe & Ito (2008), "Color Universal Design": black, orange, sky blue,
/// bluish green, yellow, blue, vermillion, reddish purple.
inline constexpr std::array<sim::Rgb, 8> kOkabeIto{0x000000, 0xe69f00, 0x56b4e9, 0x009e73,
                                                   0xf0e442, 0x0072b2, 0xd55e00, 0xcc79a7};

/// The projector theme's colour for a ball of `color`: a colour of the
/// lessons' list (lessons/colour_names.h: Okabe–Ito plus a red and a purple
/// that read as their names) is kept exactly; any other becomes the listed
/// colour nearest in hue (then lightness), so "the red ball" stays the
/// reddest ball. White and greys stay as they are (lightness needs no colour
/// vision); very dark colours become black.
sim::Rgb okabeItoColor(sim::Rgb color);

/// The colour a ball of colour `own` is drawn in with `colors` (the plain
/// theme draws `own`, the projector theme okabeItoColor(own)): the one choice
/// the balls, their trails and the tests share.
sim::Rgb drawnBallColor(sim::Rgb own, const CanvasColors& colors);

/// The canvas colours and outlines of the plain (false) or projector (true) theme.
CanvasColors canvasColors(bool projector);

} // namespace forcelab
