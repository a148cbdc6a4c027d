#include "ui/stage/arrow_legend_view.h"

#include "ui/drawing/overlays/arrow.h"
#include "ui/drawing/overlays/panel.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace forcelab {

ArrowLegendView::ArrowLegendView(QWidget* parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("stageArrowLegend"));
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    hide();
}

void ArrowLegendView::setRows(const QList<ArrowLegendRow>& rows)
{
    if (rows == m_rows)
        return;
    m_rows = rows;
    QStringList tip;
    for (const ArrowLegendRow& row : rows)
        tip << tr("An arrow this long stands for %1").arg(row.label);
    setToolTip(tip.join(QLatin1Char('\n')));
    updateGeometry();
    update();
}

double ArrowLegendView::padding() const
{
    return std::round(QFontMetricsF(font()).height() * 0.3);
}

double ArrowLegendView::widestArrow() const
{
    double widest = 0.0;
    for (const ArrowLegendRow& row : m_rows)
        widest = std::max(widest, row.pixels);
    return widest;
}

QSize ArrowLegendView::sizeHint() const
{
    if (m_rows.isEmpty())
        return {0, 0};
    const QFontMetricsF fm(font());
    double label = 0.0;
    for (const ArrowLegendRow& row : m_rows)
        label = std::max(label, fm.horizontalAdvance(row.label));
    const double pad = padding();
    const double width = 2 * pad + widestArrow() + pad + label;
    const double height = 2 * pad + static_cast<double>(m_rows.size()) * fm.height();
    return {static_cast<int>(std::ceil(width)), static_cast<int>(std::ceil(height))};
}

QSize ArrowLegendView::minimumSizeHint() const
{
    const QSize full = sizeHint();
    const double least = 3 * padding() + widestArrow() + QFontMetricsF(font()).averageCharWidth() * 8;
    return {std::min(full.width(), static_cast<int>(std::ceil(least))), full.height()};
}

// A light card like the canvas's, so the arrows keep the colours they have
// on the box (the bar itself is dark).
void ArrowLegendView::paintEvent(QPaintEvent*)
{
    if (m_rows.isEmpty())
        return;
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, true);
    // The arrows keep their length (it is what they stand for); in a
    // column narrower than the legend wants, the words get smaller to fit.
    const double pad = padding();
    const double arrows = widestArrow();
    QFont text = font();
    double widestLabel = 0.0;
    for (const ArrowLegendRow& row : m_rows)
        widestLabel = std::max(widestLabel, QFontMetricsF(text).horizontalAdvance(row.label));
    const double room = width() - 3 * pad - arrows;
    if (widestLabel > room && room > 0.0)
        text.setPointSizeF(std::max(6.0, text.pointSizeF() * room / widestLabel));
    p.setFont(text);
    const QFontMetricsF fm(text);
    drawPanelCard(p, QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5));
    const double head = std::max(6.0, fm.height() * 0.45);
    for (qsizetype i = 0; i < m_rows.size(); ++i) {
        const double y = pad + (static_cast<double>(i) + 0.5) * QFontMetricsF(font()).height();
        const QPointF tail(pad, y);
        QList<QLineF> lines;
        appendArrow(lines, tail, tail + QPointF(m_rows[i].pixels, 0.0), head);
        p.setPen(QPen(QColor::fromRgb(m_rows[i].color), std::max(2.0, fm.height() / 10), Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
        p.setPen(QColor(0x1d, 0x22, 0x2c));
        p.drawText(QPointF(pad + arrows + pad, y - fm.height() / 2 + fm.ascent()), m_rows[i].label);
    }
}

} // namespace forcelab
