#pragma once
// A panel beside the box (the readout, the totals, the legend of the force
// sources, the momenta inset): its font, its size for some lines, and how it
// is drawn, a white rounded card with its lines.

#include "sim/world/world_settings.h"

#include <QColor>
#include <QFont>
#include <QList>
#include <QRectF>
#include <QSizeF>
#include <QStringList>

#include <string_view>

class QPainter;

namespace forcelab {

/// The panels' text sizes (px at line scale 1) and line counts.
inline constexpr int kReadoutPixels = 14, kTotalsPixels = 13, kReadoutLines = 5;

/// The panels' text: a fixed-width font at a size that grows with lineScale.
QFont panelFont(int pixels, double lineScale);

/// A panel's size for `lines` lines as wide as `widest`, with its padding.
QSizeF panelSize(const QFont& font, const QString& widest, int lines, double lineScale);

/// The panels' white rounded card with its thin dark edge (the scale bar sits on one too).
void drawPanelCard(QPainter& p, const QRectF& card);

/// Draws the card and its lines, line k in colors[k] (dark text where none is given).
void drawPanel(QPainter& p, const QRectF& panel, const QFont& font, const QStringList& lines,
               const QList<QColor>& colors, double lineScale);

/// The legend of the per-source force arrows: a title and one line per model that is on.
QStringList sourceLegend(const sim::WorldSettings& settings);

/// A force model's name (sim/forces/force_models.h) in the program's language.
QString forceModelName(std::string_view name);
/// Every force model name the translation list holds, in English (for the test).
QStringList listedForceModelNames();

} // namespace forcelab
