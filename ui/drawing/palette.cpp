#include "palette.h"

#include "lessons/colour_names.h"

#include <QColor>

#include <algorithm>

#include <cmath>

namespace forcelab {

sim::Rgb okabeItoColor(sim::Rgb color)
{
    color &= 0xffffffu;
    // A colour of the lessons' list is drawn as it is: the text calls it by
    // its name, and the list's colours are the projector's colours already.
    if (lessons::isListedColour(color))
        return color;
    const QColor c = QColor::fromRgb(color);
    float h = 0, s = 0, l = 0;
    c.getHslF(&h, &s, &l);
    float hv = 0, sv = 0, v = 0;
    c.getHsvF(&hv, &sv, &v);
    if (sv < 0.2f || h < 0.0f)
        return color; // white, greys and black tell apart by lightness alone
    if (v < 0.25f)
        return 0x000000;
    // The listed colour nearest in hue, so "the red ball" of a student's
    // scene stays the reddest ball; lightness parts colours of one hue
    // (sky blue and blue), and the achromatic ones are never taken.
    sim::Rgb best = 0xe69f00;
    double closest = 1e9;
    for (const lessons::ColourName& named : lessons::colourNames()) {
        float hi = 0, si = 0, li = 0;
        QColor::fromRgb(named.color).getHslF(&hi, &si, &li);
        if (hi < 0.0f || si < 0.2f)
            continue;
        double d = std::abs(double(h) - double(hi));
        d = std::min(d, 1.0 - d) + 0.1 * std::abs(double(l) - double(li));
        if (d < closest) {
            closest = d;
            best = named.color;
        }
    }
    return best;
}

sim::Rgb drawnBallColor(sim::Rgb own, const CanvasColors& colors)
{
    return colors.colourBlindSafe ? okabeItoColor(own) : own;
}

CanvasColors canvasColors(bool projector)
{
    CanvasColors colors;
    if (!projector)
        return colors;
    colors.letterbox = 0xffe6e6e6;
    colors.background = 0xffffffff;
    colors.frame = 0xff000000;
    colors.gridMinor = 0xffececec;
    colors.gridMajor = 0xffcfcfcf;
    colors.gridText = 0xff4a4a4a;
    colors.ballOutline = 0xff000000;
    colors.outlineWidth = 2.0;
    colors.colourBlindSafe = true;
    colors.ringMarked = true;
    return colors;
}

} // namespace forcelab
