#pragma once
// The set-up every chart in the Plots panel shares: small margins, the
// legend under the plot, value axes for x and y with the series on both,
// and a view that owns exactly one chart.

#include <QList>
#include <QString>

class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;

namespace forcelab {

/// A chart with its two value axes.
struct LineChart {
    QChart* chart = nullptr; ///< not owned by anyone yet: give it to a view
    QValueAxis* x = nullptr; ///< owned by the chart
    QValueAxis* y = nullptr; ///< owned by the chart
};

/// A chart with the house margins, the legend at the bottom, an x axis
/// titled `xTitle` and a y axis, and each of `series` added and attached to
/// both (the chart takes them).
LineChart makeLineChart(const QList<QLineSeries*>& series, const QString& xTitle);

/// The house margins and legend on a chart built otherwise (bars).
void applyChartStyle(QChart* chart);

/// Shows `chart` in `view`, which takes it, and deletes the chart the view
/// made for itself: QChartView::setChart releases the old chart without
/// deleting it (a leak for every view made with the default constructor).
void setOwnChart(QChartView* view, QChart* chart);

} // namespace forcelab
