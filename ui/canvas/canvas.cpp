#include "ui/canvas/canvas.h"
#include "ui/i18n/parameter_words.h"

#include "ui/drawing/display_units.h"

#include "ui/canvas/history_recorder.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/human_number.h"

#include "sim/world/parameters.h"

#include <QApplication>

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace forcelab {

Canvas::Canvas(SimulationController* controller, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("canvas"));
    setAccessibleName(tr("Simulation stage"));
    setMouseTracking(true);
    setFocusPolicy(Qt::ClickFocus); // a click on the canvas takes focus from a spin box, so Space plays again
    setAttribute(Qt::WA_OpaquePaintEvent); // paintEvent fills every pixel
    m_options.colors = &m_colors;
    m_options.arrowRun = &m_arrowRun;
    connect(m_controller, &SimulationController::stepped, this, &Canvas::onStepped);
    connect(m_controller, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
    connect(m_controller, &SimulationController::framePassed, this, qOverload<>(&QWidget::update));
    connect(m_controller, &SimulationController::playingChanged, this, qOverload<>(&QWidget::update));
    connect(m_controller, &SimulationController::settingsChanged, this, qOverload<>(&QWidget::update));
    connect(m_controller, &SimulationController::sceneChanged, this, &Canvas::onSceneChanged);
    connect(m_controller, &SimulationController::ghostChanged, this, [this] {
        m_options.ghost = m_controller->ghost();
        update();
    });
    // Its own record until the owner gives it one (setHistory). Made after
    // the step handler above, so it records the frame after the hand has
    // put a held ball back.
    setHistory(new HistoryRecorder(m_controller, this));
}

void Canvas::setHistory(HistoryRecorder* history)
{
    if (history == m_history)
        return;
    if (m_history && m_history->parent() == this)
        delete m_history;
    m_history = history;
    m_history->setRecorded(m_options.overlays);
    m_history->setSelectedBall(m_options.selected);
    m_options.trails = &m_history->trails();
    m_options.collision = &m_history->collisionView();
    m_options.centreOfMassPath = &m_history->centreOfMassPath();
    m_options.apexes = &m_history->apexes();
    update();
}

void Canvas::setOverlays(const Overlays& overlays)
{
    const bool changed = !(overlays == m_options.overlays);
    m_options.overlays = overlays;
    m_history->setRecorded(overlays); // a path starts when it is switched on
    update();
    if (changed)
        emit overlaysChanged();
}

double Canvas::Ruler::angle() const
{
    const sim::Vec2 d = to - from;
    return std::atan2(-d.y(), d.x()) * 180.0 / std::numbers::pi;
}

double Canvas::Ruler::between() const
{
    if (!hasSecond)
        return 0.0;
    const sim::Vec2 u = (secondFromStart ? to : from) - pivot(), v = end - pivot();
    if (u.norm() == 0.0 || v.norm() == 0.0)
        return 0.0;
    // atan2 of the cross and dot products: exact at 0° and 180°, where acos
    // of the normalised dot product loses half its digits.
    const double cross = u.x() * v.y() - u.y() * v.x();
    return std::atan2(std::abs(cross), u.dot(v)) * 180.0 / std::numbers::pi;
}

namespace {

// A white card with dark bold text centred on `centre`: the ruler's numbers.
void paintRulerCard(QPainter& p, const QPointF& centre, const QString& text, double k)
{
    const QFontMetricsF fm(p.font());
    QRectF box(QPointF(0, 0), QSizeF(fm.horizontalAdvance(text) + 12 * k, fm.height() + 6 * k));
    box.moveCenter(centre);
    p.setPen(QPen(QColor(0x11, 0x11, 0x11), 1.0));
    p.setBrush(QColor(255, 255, 255, 235));
    p.drawRoundedRect(box, 4, 4);
    p.drawText(box, Qt::AlignCenter, text);
}

// One leg: the line and end ticks at right angles to it.
void paintRulerLeg(QPainter& p, const QPointF& a, const QPointF& b, double k)
{
    p.setPen(QPen(QColor(0x11, 0x11, 0x11), 2.0 * k, Qt::SolidLine, Qt::FlatCap));
    p.drawLine(a, b);
    const QLineF line(a, b);
    if (line.length() > 0.0) {
        const QPointF n = QPointF(-line.dy(), line.dx()) / line.length() * (7.0 * k);
        p.drawLine(a - n, a + n);
        p.drawLine(b - n, b + n);
    }
}

} // namespace

void Canvas::setTraceMark(const std::optional<TraceMark>& mark)
{
    m_traceMark = mark;
    update();
}

bool Canvas::showsTraceMark() const
{
    return m_traceMark && m_controller->world().stepCount() == m_traceMark->step &&
           m_traceMark->ball < m_controller->world().balls().size();
}

// Where a student's numbers put a ball: a red cross, and a card above it.
void Canvas::paintStudentCross(QPainter& p, const QPointF& at, const QString& card, double k)
{
    p.setPen(QPen(QColor(0xc0, 0x10, 0x10), 3.0 * k, Qt::SolidLine, Qt::RoundCap));
    const double arm = 8.0 * k;
    p.drawLine(at + QPointF(-arm, -arm), at + QPointF(arm, arm));
    p.drawLine(at + QPointF(-arm, arm), at + QPointF(arm, -arm));
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(14 * k)));
    font.setBold(true);
    p.setFont(font);
    const double cardHeight = QFontMetricsF(font).height() + 6 * k;
    paintRulerCard(p, at + QPointF(0, -arm - cardHeight), card, k);
}

// The student's position as a red cross, a dashed line from the ball's
// centre to it (the departure, often less than a pixel: the cross and its
// card say where), and the card.
void Canvas::paintTraceMark(QPainter& p) const
{
    const double k = m_options.lineScale;
    const QPointF ball = worldToWidget(sim::Vec2(m_controller->world().balls().position.col(m_traceMark->ball)));
    const QPointF at = worldToWidget(m_traceMark->student);
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    const QColor red(0xc0, 0x10, 0x10);
    p.setPen(QPen(red, 1.5 * k, Qt::DashLine));
    p.drawLine(ball, at);
    paintStudentCross(p, at, m_traceMark->text, k);
    p.restore();
}

QStringList Canvas::rulerTexts() const
{
    if (!m_ruler.shown)
        return {};
    const QString first = quantityText(m_ruler.length(), QStringLiteral("px"));
    if (!m_ruler.hasSecond)
        return {tr("%1 at %2°").arg(first, humanNumber(m_ruler.angle(), 3))};
    return {first, quantityText(m_ruler.secondLength(), QStringLiteral("px")),
            tr("%1°").arg(humanNumber(m_ruler.between(), 3))};
}

void Canvas::paintRuler(QPainter& p) const
{
    const QPointF a = worldToWidget(m_ruler.from), b = worldToWidget(m_ruler.to);
    const double k = m_options.lineScale;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    paintRulerLeg(p, a, b, k);
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(14 * k)));
    font.setBold(true);
    p.setFont(font);
    const double cardHeight = QFontMetricsF(font).height() + 6 * k;
    const QPointF above(0, -cardHeight);
    if (!m_ruler.hasSecond) {
        paintRulerCard(p, QLineF(a, b).center() + above, rulerTexts().value(0), k);
        p.restore();
        return;
    }
    const QPointF pivot = worldToWidget(m_ruler.pivot()), c = worldToWidget(m_ruler.end);
    const QPointF other = m_ruler.secondFromStart ? b : a;
    paintRulerLeg(p, pivot, c, k);
    // The arc of the angle at the shared end, small enough to stay on both legs.
    const QLineF legA(pivot, other), legB(pivot, c);
    const double radius = std::min(36.0 * k, 0.45 * std::min(legA.length(), legB.length()));
    double span = legB.angle() - legA.angle(); // Qt's degrees: anticlockwise as seen
    if (span > 180.0)
        span -= 360.0;
    else if (span <= -180.0)
        span += 360.0;
    if (radius > 0.0) {
        p.setPen(QPen(QColor(0x11, 0x11, 0x11), 1.5 * k));
        p.setBrush(Qt::NoBrush);
        p.drawArc(QRectF(pivot - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)),
                  static_cast<int>(std::lround(legA.angle() * 16)), static_cast<int>(std::lround(span * 16)));
    }
    // Each leg's length over its middle, the angle on the bisector past the arc.
    const QStringList texts = rulerTexts();
    paintRulerCard(p, QLineF(a, b).center() + above, texts.value(0), k);
    paintRulerCard(p, QLineF(pivot, c).center() + above, texts.value(1), k);
    QLineF bisector = QLineF::fromPolar(radius + cardHeight + 12 * k, legA.angle() + span / 2);
    bisector.translate(pivot);
    paintRulerCard(p, bisector.p2(), texts.value(2), k);
    p.restore();
}

void Canvas::setTrailsEnabled(bool enabled)
{
    Overlays o = m_options.overlays;
    o.trails = enabled;
    setOverlays(o);
}

void Canvas::setTrailScope(TrailRecorder::Scope scope)
{
    m_history->setTrailScope(scope);
    update();
}

void Canvas::setSelectedBall(int index)
{
    if (index < -1 || index >= m_controller->world().balls().size())
        index = -1;
    if (index == m_options.selected)
        return;
    m_options.selected = index;
    m_history->setSelectedBall(index);
    m_previousTime = -1.0;
    update();
    emit selectedBallChanged(index);
}

void Canvas::setMarkedColor(const QColor& color)
{
    m_painter.setMarkedColor(color.rgb() & 0xffffffu);
    update();
}

QColor Canvas::markedColor() const
{
    return QColor::fromRgb(m_painter.markedColor());
}

void Canvas::setLineScale(double scale)
{
    m_options.lineScale = scale;
    update();
}

void Canvas::setAutoArrows(bool on)
{
    m_options.autoArrows = on;
    update();
}

void Canvas::setArrowLegendCard(bool on)
{
    m_options.arrowLegendCard = on;
    update();
}

void Canvas::setColors(const CanvasColors& colors)
{
    m_colors = colors;
    update();
}

void Canvas::setArrowFactor(double factor)
{
    m_options.arrowFactor = factor;
    update();
}

void Canvas::scaleRunArrows(double factor)
{
    m_arrowRun.factor *= factor;
    update();
}

void Canvas::fixRunArrowsFromNow()
{
    m_arrowRun.clear();
    update();
}

void Canvas::setBoxMargin(double pixels)
{
    m_options.margin = pixels;
    update();
}

ViewTransform Canvas::viewTransform() const
{
    return WorldPainter::view(m_controller->world(), liveArea(), frameOptions());
}

QPointF Canvas::worldToWidget(const sim::Vec2& world) const
{
    return viewTransform().toWidget(world);
}

sim::Vec2 Canvas::widgetToWorld(const QPointF& widget) const
{
    return viewTransform().toWorld(widget);
}

int Canvas::ballAt(const QPointF& widget) const
{
    const sim::Vec2 p = widgetToWorld(widget);
    const sim::BallState& balls = m_controller->world().balls();
    // Later balls are drawn on top, so search from the end.
    for (int i = balls.size() - 1; i >= 0; --i) {
        const double r = balls.radius[i];
        if ((balls.position.col(i) - p).squaredNorm() <= r * r)
            return i;
    }
    return -1;
}

QSize Canvas::sizeHint() const
{
    return {900, 600};
}

QSize Canvas::minimumSizeHint() const
{
    return {240, 160};
}

QImage Canvas::renderImage() const
{
    return renderImage(size(), devicePixelRatioF());
}

QImage Canvas::renderImage(const QSize& size, qreal dpr) const
{
    QImage image((QSizeF(size) * dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(dpr);
    // Its own painter (and sprite cache): a screenshot leaves the canvas as it was.
    WorldPainter painter;
    painter.setMarkedColor(m_painter.markedColor());
    std::vector<WorldPainter> panes(m_panePainters.size());
    QPainter p(&image);
    paintRuns(p, QRectF(QPointF(0, 0), QSizeF(size)), painter, panes, dpr);
    return image;
}

double Canvas::paneLabelHeight() const
{
    return m_controller->comparePanes().empty() ? 0.0 : 24.0 * m_options.lineScale;
}

QList<QRectF> Canvas::paneAreas(const QRectF& area) const
{
    const int n = 1 + static_cast<int>(m_controller->comparePanes().size());
    if (n == 1)
        return {area};
    const sim::BoxSettings& box = m_controller->world().settings().box;
    const double label = paneLabelHeight();
    // Columns, rows or two by two: the grid whose cells fit the box largest.
    std::vector<std::pair<int, int>> grids{{n, 1}, {1, n}};
    if (n >= 3)
        grids.emplace_back(2, (n + 1) / 2);
    std::pair<int, int> best = grids.front();
    double bestScale = -1.0;
    for (const auto& [columns, rows] : grids) {
        const QRectF cell(0, 0, area.width() / columns, area.height() / rows - label);
        const double scale = ViewTransform::fit(box, cell, m_options.margin).scale();
        if (scale > bestScale) {
            bestScale = scale;
            best = {columns, rows};
        }
    }
    // A last row with fewer panes (three in two by two) sits in the middle,
    // so the comparison reads as one picture, not a grid with a hole.
    QList<QRectF> areas;
    const double w = area.width() / best.first, h = area.height() / best.second;
    const int lastRow = (n - 1) / best.first;
    const int inLastRow = n - lastRow * best.first;
    for (int k = 0; k < n; ++k) {
        const int row = k / best.first;
        const double indent = row == lastRow ? (best.first - inLastRow) * w / 2 : 0.0;
        areas.append(QRectF(area.left() + indent + (k % best.first) * w, area.top() + row * h, w, h));
    }
    return areas;
}

QRectF Canvas::liveArea() const
{
    return paneAreas(QRectF(rect())).front().adjusted(0, paneLabelHeight(), 0, 0);
}

void Canvas::paintRuns(QPainter& p, const QRectF& area, WorldPainter& live, std::vector<WorldPainter>& panes,
                       qreal dpr) const
{
    const std::vector<SimulationController::Pane>& runs = m_controller->comparePanes();
    const PaintOptions options = frameOptions();
    if (runs.empty()) {
        live.paint(p, area, m_controller->world(), options, dpr);
        return;
    }
    const QList<QRectF> areas = paneAreas(area);
    const double label = paneLabelHeight();
    p.fillRect(area, QColor::fromRgb(m_colors.letterbox));
    live.paint(p, areas[0].adjusted(0, label, 0, 0), m_controller->world(), options, dpr);
    // The panes show the balls, the box and the paths through the same
    // camera; the panels (readout, totals, momenta) and the selection belong
    // to the live run.
    PaintOptions own = options;
    own.overlays.readout = own.overlays.totals = own.overlays.momenta = own.overlays.forceSources = false;
    own.overlays.impact = false;
    own.selected = -1;
    own.ghost = nullptr;
    own.positions = nullptr;
    own.collision = nullptr;
    own.centreOfMassPath = nullptr;
    panes.resize(runs.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        if (!runs[k].world)
            continue;
        own.trails = k < m_history->paneTrails().size() ? &m_history->paneTrails()[k] : nullptr;
        panes[k].setMarkedColor(live.markedColor());
        panes[k].paint(p, areas[static_cast<qsizetype>(k) + 1].adjusted(0, label, 0, 0), *runs[k].world, own, dpr);
    }
    // The labels, over each run's strip.
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(15 * m_options.lineScale)));
    font.setBold(true);
    p.setFont(font);
    p.setPen(QColor(0x1d, 0x22, 0x2c));
    const QStringList labels = paneLabels();
    const QFontMetricsF fm(font);
    for (qsizetype k = 0; k < areas.size(); ++k) {
        const QRectF strip(areas[k].left() + 10, areas[k].top(), areas[k].width() - 20, label);
        const bool failed = k > 0 && runs[static_cast<std::size_t>(k - 1)].student &&
                            (runs[static_cast<std::size_t>(k - 1)].student->error() ||
                             runs[static_cast<std::size_t>(k - 1)].student->departure());
        p.setPen(failed ? QColor(0xb0, 0x10, 0x10) : QColor(0x1d, 0x22, 0x2c));
        p.drawText(strip, Qt::AlignLeft | Qt::AlignVCenter,
                   fm.elidedText(labels.value(k), Qt::ElideRight, strip.width()));
    }
    // Where a student's code first departed from the reference: marked in its pane.
    for (std::size_t k = 0; k < runs.size(); ++k)
        if (runs[k].student && runs[k].world && runs[k].student->departure())
            paintDeparture(p, areas[static_cast<qsizetype>(k) + 1].adjusted(0, label, 0, 0), *runs[k].world,
                           *runs[k].student->departure(), own);
}

QStringList Canvas::paneLabels() const
{
    const std::vector<SimulationController::Pane>& runs = m_controller->comparePanes();
    if (runs.empty())
        return {};
    QStringList labels;
    if (const StudentRun* student = m_controller->studentRun()) {
        // The student's code beside the reference: each with its energy, and
        // the student's with how far it has come or where it departed.
        const auto energy = [](const sim::World& w) {
            return quantityText(w.energy().total(), WorldPainter::kEnergyUnit, 4);
        };
        labels << tr("reference (the course's code) · energy %1").arg(energy(m_controller->world()));
        for (const SimulationController::Pane& pane : runs) {
            if (!pane.student) {
                labels << pane.label;
                continue;
            }
            if (student->error())
                labels << tr("your code stopped: %1").arg(student->error()->text());
            else if (const auto& d = student->departure(); d && d->ball < 0)
                labels << tr("your code departs at step %1: %2 balls, the reference has %3")
                              .arg(d->step).arg(d->student).arg(d->reference);
            else if (d)
                labels << tr("your code departs at step %1 (ball %2, %3 off by %4) · energy %5")
                              .arg(d->step)
                              .arg(d->ball)
                              .arg(d->field,
                                   quantityText(d->size(), d->field.startsWith(QLatin1Char('v')) ? QStringLiteral("px/s")
                                                                                               : QStringLiteral("px"), 3),
                                   pane.world ? energy(*pane.world) : QString());
            else
                labels << tr("your code · agrees for %1 steps · energy %2")
                              .arg(student->steps())
                              .arg(pane.world ? energy(*pane.world) : QString());
        }
        return labels;
    }
    // The live run is named by its own values of what the panes change
    // ("your run: clamp"), so the three labels read as one comparison.
    QStringList liveValues;
    std::vector<std::string> keys;
    for (const SimulationController::Pane& pane : runs)
        for (const auto& entry : pane.set)
            if (std::find(keys.begin(), keys.end(), entry.first) == keys.end())
                keys.push_back(entry.first);
    for (const std::string& key : keys)
        if (const sim::Parameter* row = sim::findParameter(key)) {
            const double value = row->get(m_controller->world().settings());
            if (row->type == sim::ParameterType::Choice) {
                const auto names = row->choices();
                const auto i = static_cast<std::size_t>(value);
                if (i < names.size())
                    liveValues << QString::fromLatin1(names[i].data(), static_cast<qsizetype>(names[i].size()));
            } else if (row->type == sim::ParameterType::Boolean) {
                liveValues << QStringLiteral("%1 %2").arg(parameterLabel(*row), value != 0.0 ? tr("on") : tr("off"));
            } else {
                liveValues << QStringLiteral("%1 %2").arg(parameterLabel(*row))
                           .arg(value, 0, 'g', 4);
            }
        }
    labels << tr("your run: %1").arg(liveValues.join(QStringLiteral(", ")));
    for (const SimulationController::Pane& pane : runs)
        labels << pane.label;
    return labels;
}

// A red cross where the student's ball was at the step it departed, a ring
// where the reference had it, and a card with the step: the two are often
// less than a pixel apart, so the card says what the eye cannot see.
void Canvas::paintDeparture(QPainter& p, const QRectF& area, const sim::World& pane, const ScriptDeparture& d,
                            const PaintOptions& paneOptions) const
{
    if (d.ball < 0)
        return;
    const ViewTransform view = WorldPainter::view(pane, area, paneOptions); // the pane's own layout (no readout)
    const double k = m_options.lineScale;
    const QPointF at = view.toWidget(d.studentPosition);
    const QPointF ref = view.toWidget(d.referencePosition);
    p.save();
    p.setClipRect(area);
    p.setRenderHint(QPainter::Antialiasing, true);
    const QColor red(0xc0, 0x10, 0x10);
    p.setPen(QPen(red, 2.0 * k));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(ref, 10.0 * k, 10.0 * k);
    paintStudentCross(p, at, tr("departs here, step %1").arg(d.step), k);
    p.restore();
}

bool Canvas::showsStartHint() const
{
    return !m_controller->isPlaying() && m_controller->world().time() == 0.0;
}

void Canvas::setToolKeys(const QStringList& keys)
{
    m_toolKeys = keys;
    update();
}

// A lesson opens paused at t = 0: a banner at the bottom of the stage says
// how to start it and which keys open the lesson's tools, large enough for
// the back of a classroom.
void Canvas::paintStartHint(QPainter& p) const
{
    QString text = tr("Paused at t = 0 · press Space to run");
    if (!m_toolKeys.isEmpty())
        text += QLatin1Char('\n') + tr("Tools: press %1").arg(m_toolKeys.join(QStringLiteral(" · ")));
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(18 * m_options.lineScale)));
    font.setBold(true);
    p.setFont(font);
    const QFontMetricsF fm(font);
    const double pad = 10.0 * m_options.lineScale;
    const QSizeF size(fm.boundingRect(QRectF(), 0, text).width() + 2 * pad,
                      fm.lineSpacing() * (1 + text.count(QLatin1Char('\n'))) + pad);
    const QRectF banner(QPointF(0.5 * (width() - size.width()), height() - size.height() - 2 * pad), size);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x1d, 0x22, 0x2c, 220));
    p.drawRoundedRect(banner, pad, pad);
    p.setPen(Qt::white);
    p.drawText(banner, Qt::AlignCenter, text);
}

void Canvas::paintEvent(QPaintEvent*)
{
    QElapsedTimer timer;
    timer.start();
    QPainter painter(this);
    m_options.positions = m_controller->interpolatedPositions();
    if (m_following) // the view stays where the ball was last drawn if it goes (deleted, deselected)
        m_options.camera = shownCamera();
    paintRuns(painter, QRectF(rect()), m_painter, m_panePainters, devicePixelRatioF());
    if (m_ruler.shown)
        paintRuler(painter);
    if (showsTraceMark())
        paintTraceMark(painter);
    if (showsStartHint())
        paintStartHint(painter);
    ++m_frames;
    m_lastPaintMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    if (const QList<ArrowLegendRow>& rows = m_painter.lastFrame().arrowLegendRows; rows != m_arrowLegend) {
        m_arrowLegend = rows;
        emit arrowLegendChanged(rows);
    }
}

void Canvas::mouseMoveEvent(QMouseEvent* event)
{
    if (m_panning) {
        panBy(event->position() - m_panFrom);
        m_panFrom = event->position();
        return;
    }
    if (m_measuring) {
        (m_measuringSecond ? m_ruler.end : m_ruler.to) = widgetToWorld(event->position());
        update();
        return;
    }
    m_lastPointer = event->position();
    if (m_arrow.ball >= 0) {
        arrowTo(event->position(), event->modifiers());
        return;
    }
    if (m_press.ball >= 0) { // pressed on a ball: taken once the pointer has moved far enough
        if ((event->buttons() & Qt::LeftButton) &&
            (event->position() - m_press.at).manhattanLength() >= QApplication::startDragDistance())
            startDrag(event->position(), static_cast<qint64>(event->timestamp()));
        return;
    }
    if (m_drag.ball >= 0) {
        dragTo(event->position(), static_cast<qint64>(event->timestamp()));
        return;
    }
    sendPointer(event->position(), true, (event->buttons() & Qt::LeftButton) != 0);
}

void Canvas::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier)) {
        // The ruler: measuring never touches the physics. A drag from an
        // end of the line there is draws its second leg; elsewhere, a new ruler.
        const auto near = [&](const sim::Vec2& world) {
            return QLineF(worldToWidget(world), event->position()).length() <= kTipGrabPixels * m_options.lineScale;
        };
        m_measuringSecond = m_ruler.shown && (near(m_ruler.from) || near(m_ruler.to));
        if (m_measuringSecond) {
            m_ruler.secondFromStart = near(m_ruler.from) &&
                                      (!near(m_ruler.to) || QLineF(worldToWidget(m_ruler.from), event->position()).length() <
                                                                QLineF(worldToWidget(m_ruler.to), event->position()).length());
            m_ruler.hasSecond = true;
            m_ruler.end = m_ruler.pivot();
        } else {
            m_ruler = Ruler();
            m_ruler.shown = true;
            m_ruler.from = m_ruler.to = widgetToWorld(event->position());
        }
        m_measuring = true;
        update();
        return;
    }
    if (m_ruler.shown) {
        m_ruler.shown = false; // a plain click puts the ruler away
        update();
    }
    if (startsPan(*event)) { // moving the view never touches the physics
        m_panning = true;
        m_panFrom = event->position();
        setCursor(Qt::ClosedHandCursor);
        sendPointer(event->position(), false, false);
        return;
    }
    if (event->button() == Qt::LeftButton) {
        const int ball = ballAt(event->position());
        if (grabsArrow(event->position(), event->modifiers(), ball)) {
            startArrowDrag((event->modifiers() & Qt::AltModifier) && ball >= 0 ? ball : m_options.selected);
            arrowTo(event->position(), event->modifiers());
            return;
        }
        setSelectedBall(ball);
        if (ball >= 0) {
            // Select it and arm a grab; pointer forces stay off while the
            // button is down on a ball, so only the hand may move it.
            m_press = Press{ball, event->position(), static_cast<qint64>(event->timestamp())};
            sendPointer(event->position(), false, false);
            return;
        }
    }
    sendPointer(event->position(), true, (event->buttons() & Qt::LeftButton) != 0);
}

void Canvas::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_panning) {
        if (!(event->buttons() & (Qt::LeftButton | Qt::MiddleButton))) {
            m_panning = false;
            unsetCursor();
        }
        return;
    }
    if (m_measuring && event->button() == Qt::LeftButton) {
        (m_measuringSecond ? m_ruler.end : m_ruler.to) = widgetToWorld(event->position());
        m_measuring = false;
        update();
        return;
    }
    if (event->button() == Qt::LeftButton && m_arrow.ball >= 0) {
        arrowTo(event->position(), event->modifiers());
        finishArrowDrag();
        return;
    }
    if (event->button() == Qt::LeftButton && m_press.ball >= 0) { // a click: it selected, nothing else
        m_press = Press();
        sendPointer(event->position(), true, false);
        return;
    }
    if (event->button() == Qt::LeftButton && m_drag.ball >= 0) {
        const qint64 now = static_cast<qint64>(event->timestamp());
        dragTo(event->position(), now);
        // The throw: the pointer's mean velocity over the last kThrowWindowMs,
        // from the last sample at or before the window's start (or the
        // oldest) to the release. A pointer that stood still is a drop.
        const auto& samples = m_drag.samples;
        auto start = samples.begin();
        for (auto it = samples.begin(); it != samples.end() && it->first <= now - kThrowWindowMs; ++it)
            start = it;
        const std::pair<qint64, sim::Vec2>& last = samples.back();
        const double seconds = static_cast<double>(last.first - start->first) * 1e-3;
        const sim::Vec2 velocity = seconds > 0.0 ? sim::Vec2((last.second - start->second) / seconds) : sim::Vec2(0, 0);
        const Drag drag = m_drag;
        m_drag = Drag();
        finishDrag(drag, velocity);
    }
    sendPointer(event->position(), true, (event->buttons() & Qt::LeftButton) != 0);
}

void Canvas::leaveEvent(QEvent*)
{
    // Pointer wind and pointer forces stop when the pointer leaves (a held
    // ball stays held: the pointer is grabbed while a button is down).
    sendPointer(QPointF(), false, false);
}

void Canvas::startDrag(const QPointF& widget, qint64 timestampMs)
{
    // Take the ball where it was pressed: it keeps its offset from that point
    // and catches up with the pointer.
    const Press press = m_press;
    m_press = Press();
    if (press.ball >= m_controller->world().balls().size())
        return;
    m_drag.ball = press.ball;
    m_drag.before = m_controller->world().balls().ball(press.ball);
    m_drag.offset = sim::Vec2(m_controller->world().balls().position.col(press.ball)) - widgetToWorld(press.at);
    m_drag.samples.clear();
    dragTo(press.at, press.ms);
    dragTo(widget, timestampMs);
}

void Canvas::dragTo(const QPointF& widget, qint64 timestampMs)
{
    const sim::Vec2 at = widgetToWorld(widget);
    auto& samples = m_drag.samples;
    if (!samples.empty() && timestampMs < samples.back().first)
        timestampMs = samples.back().first; // timestamps never run backwards
    samples.emplace_back(timestampMs, at);
    // Keep one sample older than the throw window, for its start.
    while (samples.size() > 2 && samples[1].first <= timestampMs - kThrowWindowMs)
        samples.pop_front();
    m_drag.target = at + m_drag.offset;
    holdDraggedBall();
    if (m_controller->isPlaying())
        update(); // the next frame shows it to everyone
    else
        m_controller->notifyBallsChanged();
}

void Canvas::holdDraggedBall()
{
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (m_drag.ball < 0 || m_drag.ball >= balls.size())
        return;
    balls.position.col(m_drag.ball) = m_drag.target;
    balls.velocity.col(m_drag.ball).setZero();
    m_controller->noteHandMoved();
}

void Canvas::sendPointer(const QPointF& widget, bool inside, bool pressed)
{
    sim::PointerInput input;
    input.inside = inside;
    input.pressed = inside && pressed;
    input.position = inside ? widgetToWorld(widget) : m_controller->world().pointer().position;
    m_controller->setPointer(input);
    if (!m_controller->isPlaying() && m_controller->world().settings().pointer.enabled)
        update();
}

void Canvas::onSceneChanged()
{
    if (m_controller->sceneSerial() != m_sceneSerial) { // a new lesson, not a reset: its arrows get their own scale
        m_sceneSerial = m_controller->sceneSerial();
        m_arrowRun.clear();
    }
    if (m_arrow.ball >= 0) { // a new scene ends an arrow drag with no edit
        m_options.autoArrows = m_arrow.autoArrows;
        m_options.velocityScale = m_arrow.velocityScale;
        m_options.arrowFactor = m_arrow.arrowFactor;
        m_arrow = ArrowDrag();
    }
    m_drag = Drag();
    m_press = Press();
    m_ruler = Ruler(); // it measured the scene that went (a reset or a new lesson)
    m_traceMark.reset();
    m_measuring = false;
    m_previousTime = -1.0; // the recorder starts over too
    if (m_options.selected >= m_controller->world().balls().size())
        setSelectedBall(-1);
    update();
}

void Canvas::onStepped()
{
    const sim::World& world = m_controller->world();
    if (m_drag.ball >= 0 && world.time() != m_previousTime)
        holdDraggedBall(); // the steps of this frame moved it; the hand holds it
    m_previousTime = world.time();
}

} // namespace forcelab
