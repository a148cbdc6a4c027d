#include "ui/window/theme.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QColor>
#include <QLegend>
#include <QWidget>

#include <cmath>
#include <optional>

namespace forcelab {

namespace {
std::optional<QFont> g_desktopFont; // the application's font before the projector theme
}

void applyProjectorFonts(QWidget* root, bool projector, double textScale)
{
    if (!g_desktopFont)
        g_desktopFont = QApplication::font();
    QFont font = *g_desktopFont;
    const double scale = (projector ? kProjectorFontScale : 1.0) * textScale;
    if (scale != 1.0) {
        if (font.pointSizeF() > 0)
            font.setPointSizeF(font.pointSizeF() * scale);
        else
            font.setPixelSize(static_cast<int>(std::lround(font.pixelSize() * scale)));
    }
    QApplication::setFont(font);
    if (!root)
        return;
    // Charts keep fonts of their own: their titles, axes and legends follow
    // the application's font explicitly.
    for (QChartView* view : root->findChildren<QChartView*>()) {
        QChart* chart = view->chart();
        if (!chart)
            continue;
        QFont title = font;
        title.setBold(true);
        chart->setTitleFont(title);
        chart->legend()->setFont(font);
        for (QAbstractAxis* axis : chart->axes()) {
            axis->setLabelsFont(font);
            axis->setTitleFont(font);
        }
    }
}

} // namespace forcelab
