#include "ui/charts/chart_setup.h"

#include <QChart>
#include <QChartView>
#include <QLegend>
#include <QLineSeries>
#include <QValueAxis>

namespace forcelab {

void applyChartStyle(QChart* chart)
{
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setMargins(QMargins(4, 4, 4, 4));
}

LineChart makeLineChart(const QList<QLineSeries*>& series, const QString& xTitle)
{
    LineChart made;
    made.chart = new QChart();
    applyChartStyle(made.chart);
    made.x = new QValueAxis(made.chart);
    made.x->setTitleText(xTitle);
    made.y = new QValueAxis(made.chart);
    made.chart->addAxis(made.x, Qt::AlignBottom);
    made.chart->addAxis(made.y, Qt::AlignLeft);
    for (QLineSeries* s : series) {
        made.chart->addSeries(s);
        s->attachAxis(made.x);
        s->attachAxis(made.y);
    }
    return made;
}

void setOwnChart(QChartView* view, QChart* chart)
{
    QChart* made = view->chart();
    view->setChart(chart);
    if (made != chart)
        delete made;
}

} // namespace forcelab
