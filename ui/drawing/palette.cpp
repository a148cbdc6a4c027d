#include "palette.h"

#include <QColor>

#include <cmath>

namespace forcelab {

sim::Rgb okabeItoColor(sim::Rgb color)
{
    const QColor c = QColor::fromRgb(color);
    float h = 0, s = 0, v = 0;
    c.getHsvF(&h, &s, &v);
    if (s < 0.2f || h < 0.0f)
        return color; // white, greys and black tell apart by lightness alone
    if (v < 0.25f)
        return kOkabeIto[0];
    // Hue distance on the colour circle to each of the seven colours.
    sim::Rgb best = kOkabeIto[1];
    double closest = 2.0;
    for (std::size_t i = 1; i < kOkabeIto.size(); ++i) {
        float hi = 0, si = 0, vi = 0;
        QColor::fromRgb(kOkabeIto[i]).getHsvF(&hi, &si, &vi);
        double d = std::abs(double(h) - double(hi));
        d = std::min(d, 1.0 - d);
        if (d < closest) {
            closest = d;
            best = kOkabeIto[i];
        }
    }
    return best;
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
