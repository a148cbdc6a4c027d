#include "canvas.h"

#include "simulation_controller.h"

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QPainter>

namespace forcelab {

Canvas::Canvas(SimulationController* controller, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("canvas"));
    setMouseTracking(true);
    setFocusPolicy(Qt::ClickFocus); // a click on the canvas takes focus from a spin box, so Space plays again
    setAttribute(Qt::WA_OpaquePaintEvent); // paintEvent fills every pixel
    connect(m_controller, &SimulationController::stepped, this, qOverload<>(&QWidget::update));
    connect(m_controller, &SimulationController::settingsChanged, this, qOverload<>(&QWidget::update));
    connect(m_controller, &SimulationController::sceneChanged, this, &Canvas::onSceneChanged);
}

void Canvas::setOverlays(const Overlays& overlays)
{
    m_options.overlays = overlays;
    update();
}

void Canvas::setSelectedBall(int index)
{
    if (index < -1 || index >= m_controller->world().balls().size())
        index = -1;
    if (index == m_options.selected)
        return;
    m_options.selected = index;
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

ViewTransform Canvas::viewTransform() const
{
    return WorldPainter::view(m_controller->world(), QRectF(rect()));
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

void Canvas::paintEvent(QPaintEvent*)
{
    QElapsedTimer timer;
    timer.start();
    QPainter painter(this);
    m_painter.paint(painter, QRectF(rect()), m_controller->world(), m_options, devicePixelRatioF());
    ++m_frames;
    m_lastPaintMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
}

void Canvas::mouseMoveEvent(QMouseEvent* event)
{
    sendPointer(event->position(), true, (event->buttons() & Qt::LeftButton) != 0);
}

void Canvas::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        setSelectedBall(ballAt(event->position()));
    sendPointer(event->position(), true, (event->buttons() & Qt::LeftButton) != 0);
}

void Canvas::mouseReleaseEvent(QMouseEvent* event)
{
    sendPointer(event->position(), true, (event->buttons() & Qt::LeftButton) != 0);
}

void Canvas::leaveEvent(QEvent*)
{
    // Pointer wind and pointer forces stop when the pointer leaves.
    sendPointer(QPointF(), false, false);
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
    if (m_options.selected >= m_controller->world().balls().size())
        setSelectedBall(-1);
    update();
}

} // namespace forcelab
