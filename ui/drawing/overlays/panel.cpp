// The panels' font, size and card (panel.h).

#include "panel.h"

#include "sim/forces/force_models.h"

#include <QCoreApplication>
#include <QFontDatabase>
#include <QFontMetricsF>
#include <QPainter>
#include <QPen>

#include <cmath>

namespace forcelab {

QFont panelFont(int pixels, double lineScale)
{
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPixelSize(static_cast<int>(std::lround(pixels * lineScale)));
    return font;
}

QSizeF panelSize(const QFont& font, const QString& widest, int lines, double lineScale)
{
    const QFontMetricsF fm(font);
    const double pad = 8.0 * lineScale;
    return {fm.horizontalAdvance(widest) + 2 * pad, fm.lineSpacing() * lines + 2 * pad};
}

void drawPanelCard(QPainter& p, const QRectF& card)
{
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(QColor(0x2d, 0x33, 0x40, 160), 1.0));
    p.setBrush(QColor(255, 255, 255, 235));
    p.drawRoundedRect(card, 6, 6);
}

void drawPanel(QPainter& p, const QRectF& panel, const QFont& font, const QStringList& lines,
               const QList<QColor>& colors, double lineScale)
{
    p.setFont(font);
    const QFontMetricsF fm(font);
    const double pad = 8.0 * lineScale;
    drawPanelCard(p, panel);
    double y = panel.top() + pad + fm.ascent();
    for (qsizetype k = 0; k < lines.size(); ++k) {
        p.setPen(colors.value(k, QColor(0x1d, 0x22, 0x2c)));
        p.drawText(QPointF(panel.left() + pad, y), lines[k]);
        y += fm.lineSpacing();
    }
}

namespace {

// sim's force models by name (sim/forces/force_models.cpp), listed for
// lupdate; test_translations fails when a model is missing here.
constexpr const char* kForceNames[] = {
    QT_TRANSLATE_NOOP("ForceModel", "gravity"),      QT_TRANSLATE_NOOP("ForceModel", "drag"),
    QT_TRANSLATE_NOOP("ForceModel", "wind"),         QT_TRANSLATE_NOOP("ForceModel", "random"),
    QT_TRANSLATE_NOOP("ForceModel", "point force"),  QT_TRANSLATE_NOOP("ForceModel", "pointer"),
    QT_TRANSLATE_NOOP("ForceModel", "spring"),       QT_TRANSLATE_NOOP("ForceModel", "homing"),
    QT_TRANSLATE_NOOP("ForceModel", "between balls"), QT_TRANSLATE_NOOP("ForceModel", "magnetic"),
    QT_TRANSLATE_NOOP("ForceModel", "custom force"),
};

} // namespace

QString forceModelName(std::string_view name)
{
    const QByteArray english(name.data(), static_cast<qsizetype>(name.size()));
    return QCoreApplication::translate("ForceModel", english.constData());
}

QStringList listedForceModelNames()
{
    QStringList out;
    for (const char* name : kForceNames)
        out << QString::fromUtf8(name);
    return out;
}

QStringList sourceLegend(const sim::WorldSettings& settings)
{
    QStringList lines{QCoreApplication::translate("Overlay", "forces by source")};
    for (const sim::ForceModelInfo& m : sim::forceModels())
        if (m.on(settings))
            lines.append(QStringLiteral("── ") + forceModelName(m.name));
    return lines;
}

} // namespace forcelab
