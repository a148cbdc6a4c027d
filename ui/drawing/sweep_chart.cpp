#include "sweep_chart.h"
#include "png_file.h"

#include "sim/integrators/integrator_info.h"
#include "sim/world/names.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace forcelab {

using namespace sim;

namespace {


QColor integratorColor(IntegratorKind k)
{
    static const QRgb colors[] = {0xd62728, 0xff7f0e, 0x2ca02c, 0x1f77b4, 0x9467bd, 0x8c564b, 0x7f7f7f, 0x111111};
    return QColor::fromRgb(colors[static_cast<int>(k) % 8]);
}

double floorLog(double v) { return std::floor(std::log10(v)); }
double ceilLog(double v) { return std::ceil(std::log10(v)); }

void drawPanel(QPainter& p, const QRectF& area, const ReferenceProblem& problem, const std::vector<SweepRun>& all)
{
    std::vector<const SweepRun*> rows;
    for (const SweepRun& r : all)
        if (r.problem == problem.name && !r.blewUp && r.evaluations > 0)
            rows.push_back(&r);
    // Exact results are drawn on the floor; an error beyond 100 times the
    // problem's size (the orbit is lost) is drawn on the ceiling.
    static constexpr double kErrorFloor = 1e-16;
    const double ceiling = std::pow(10.0, ceilLog(100.0 * problem.length));
    auto errorOf = [=](const SweepRun* r) { return std::clamp(r->positionError, kErrorFloor, ceiling); };
    double xMin = 1e300, xMax = 0, yMin = 1e300, yMax = 0;
    for (const SweepRun* r : rows) {
        xMin = std::min(xMin, double(r->evaluations));
        xMax = std::max(xMax, double(r->evaluations));
        yMin = std::min(yMin, errorOf(r));
        yMax = std::max(yMax, errorOf(r));
    }
    if (rows.empty()) {
        xMin = 1;
        xMax = 10;
        yMin = 1e-16;
        yMax = 1;
    }
    const double lx0 = floorLog(xMin), lx1 = std::max(ceilLog(xMax), lx0 + 1);
    const double ly0 = floorLog(yMin), ly1 = std::max(ceilLog(yMax), ly0 + 1);

    p.save(); // each panel starts from the same pen, brush and font
    p.fillRect(area, Qt::white);
    QFont font = p.font();
    font.setPixelSize(13);
    p.setFont(font);
    const QRectF plot = area.adjusted(78, 40, -170, -56);
    auto X = [&](double v) { return plot.left() + (std::log10(v) - lx0) / (lx1 - lx0) * plot.width(); };
    auto Y = [&](double v) { return plot.bottom() - (std::log10(v) - ly0) / (ly1 - ly0) * plot.height(); };

    // Grid and tick labels at every power of ten (every other one when crowded).
    const int yStep = ly1 - ly0 > 10 ? 2 : 1;
    p.setPen(QPen(QColor(0xdd, 0xe1, 0xe7), 1));
    for (int e = int(lx0); e <= int(lx1); ++e)
        p.drawLine(QPointF(X(std::pow(10.0, e)), plot.top()), QPointF(X(std::pow(10.0, e)), plot.bottom()));
    for (int e = int(ly0); e <= int(ly1); e += yStep)
        p.drawLine(QPointF(plot.left(), Y(std::pow(10.0, e))), QPointF(plot.right(), Y(std::pow(10.0, e))));
    p.setPen(Qt::black);
    p.setBrush(Qt::NoBrush);
    p.drawRect(plot);
    for (int e = int(lx0); e <= int(lx1); ++e)
        p.drawText(QRectF(X(std::pow(10.0, e)) - 30, plot.bottom() + 4, 60, 18), Qt::AlignHCenter | Qt::AlignTop,
                   QStringLiteral("1e%1").arg(e));
    for (int e = int(ly0); e <= int(ly1); e += yStep)
        p.drawText(QRectF(plot.left() - 64, Y(std::pow(10.0, e)) - 9, 58, 18), Qt::AlignRight | Qt::AlignVCenter,
                   QStringLiteral("1e%1").arg(e));
    p.drawText(QRectF(plot.left(), plot.bottom() + 26, plot.width(), 20), Qt::AlignHCenter,
               QStringLiteral("cost: force evaluations (log scale)"));
    p.save();
    p.translate(area.left() + 16, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, -10, plot.height(), 20), Qt::AlignHCenter,
               QStringLiteral("position error at the end, px (log scale)"));
    p.restore();
    QFont title = font;
    title.setPixelSize(15);
    title.setBold(true);
    p.setFont(title);
    p.drawText(QRectF(plot.left(), area.top() + 8, plot.width() + 160, 24), Qt::AlignLeft,
               QString::fromStdString(problem.what));
    p.setFont(font);

    // One line per integrator (and per swept dt for the adaptive ones), in
    // order of cost, with a dot at each run.
    p.setRenderHint(QPainter::Antialiasing);
    int legendRow = 0;
    for (std::size_t k = 0; k < integratorNames().size(); ++k) {
        const auto kind = static_cast<IntegratorKind>(k);
        std::vector<const SweepRun*> line;
        // Adaptive methods: their tolerance sweep at the outer step of 1/16 s.
        const bool adaptive = integratorInfo(kind).adaptive;
        for (const SweepRun* r : rows)
            if (r->integrator == kind && (!adaptive || r->dt == 1.0 / 16))
                line.push_back(r);
        if (line.empty())
            continue;
        std::sort(line.begin(), line.end(), [](const SweepRun* a, const SweepRun* b) { return a->evaluations < b->evaluations; });
        const QColor color = integratorColor(kind);
        QPainterPath path;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const QPointF pt(X(double(line[i]->evaluations)), Y(errorOf(line[i])));
            i ? path.lineTo(pt) : path.moveTo(pt);
        }
        p.setPen(QPen(color, 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setBrush(color);
        for (const SweepRun* r : line)
            p.drawEllipse(QPointF(X(double(r->evaluations)), Y(errorOf(r))), 3, 3);
        // Legend entry.
        const QPointF at(plot.right() + 16, plot.top() + 8 + 22 * legendRow++);
        p.drawLine(at, at + QPointF(24, 0));
        p.setPen(Qt::black);
        p.drawText(QRectF(at.x() + 30, at.y() - 9, 130, 18), Qt::AlignLeft | Qt::AlignVCenter,
                   QString::fromLatin1(toString(kind).data(), int(toString(kind).size())));
    }
    p.restore();
}

constexpr int kPanelWidth = 760;
constexpr int kPanelHeight = 480;

} // namespace

bool writeSweepChart(const QString& file, const std::vector<sim::ReferenceProblem>& problems,
                     const std::vector<sim::SweepRun>& rows, QString* error)
{
    const int n = int(problems.size());
    const int columns = std::min(n, 2), lines = (n + columns - 1) / columns;
    QImage image(columns * kPanelWidth, lines * kPanelHeight, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    for (int i = 0; i < n; ++i)
        drawPanel(painter, QRectF((i % columns) * kPanelWidth, (i / columns) * kPanelHeight, kPanelWidth, kPanelHeight),
                  problems[i], rows);
    painter.end();
    return writePngAtomically(file, image, error);
}


} // namespace forcelab
