// The canvas's camera: zoom about the pointer, pan, fit the box or all the
// balls, and follow the selected ball. The camera lives in the paint options
// (PaintOptions::camera), so every picture and every hit test of the canvas
// uses the same view.

#include "ui/canvas/canvas.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/overlays/overlay.h"

#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab {

Camera Canvas::shownCamera() const
{
    Camera camera = m_options.camera;
    const sim::BallState& balls = m_controller->world().balls();
    const int i = m_options.selected;
    if (m_following && i >= 0 && i < balls.size()) {
        const sim::Vec2 at = drawnPositions(balls, m_options).col(i);
        if (at.allFinite())
            camera.centre = at;
    }
    return camera;
}

PaintOptions Canvas::frameOptions() const
{
    PaintOptions options = m_options;
    options.camera = shownCamera();
    return options;
}

void Canvas::setCamera(const Camera& camera)
{
    if (camera == m_options.camera)
        return;
    m_options.camera = camera;
    update();
    emit cameraChanged();
}

// The scale of the fitted view (widget px per world px), which the zoom multiplies.
double Canvas::fittedScale(const ViewTransform& view) const
{
    return view.scale() / shownCamera().zoom;
}

void Canvas::zoomAbout(double factor, const QPointF& widget)
{
    const ViewTransform view = viewTransform();
    Camera camera = shownCamera();
    const double zoom = std::clamp(camera.zoom * factor, Camera::kMinZoom, Camera::kMaxZoom);
    if (!(zoom > 0.0) || zoom == camera.zoom || !(view.scale() > 0.0))
        return;
    const double fitted = fittedScale(view);
    const QPointF middle = view.area().center();
    // While following, the ball stays in the middle: zoom about it.
    const QPointF anchor = m_following ? middle : widget;
    const sim::Vec2 under = view.toWorld(anchor);
    // The world point under the anchor stays there: middle + (under − centre) · scale = anchor.
    const QPointF d = (anchor - middle) / (fitted * zoom);
    camera.zoom = zoom;
    camera.centre = sim::Vec2(under.x() - d.x(), under.y() - d.y());
    setCamera(camera);
}

void Canvas::zoomIn()
{
    zoomAbout(kZoomStep, viewTransform().area().center());
}

void Canvas::zoomOut()
{
    zoomAbout(1.0 / kZoomStep, viewTransform().area().center());
}

void Canvas::panBy(const QPointF& widgetDelta)
{
    setFollowing(false);
    const ViewTransform view = viewTransform();
    if (!(view.scale() > 0.0))
        return;
    Camera camera = m_options.camera;
    const sim::Vec2 middle = view.toWorld(view.area().center());
    camera.centre = sim::Vec2(middle.x() - widgetDelta.x() / view.scale(), middle.y() - widgetDelta.y() / view.scale());
    setCamera(camera);
}

void Canvas::fitBox()
{
    setFollowing(false);
    setCamera(Camera());
}

Camera Canvas::allBallsCamera() const
{
    const sim::BallState& balls = m_controller->world().balls();
    const sim::Matrix2X& at = drawnPositions(balls, m_options);
    double left = std::numeric_limits<double>::infinity(), top = left;
    double right = -left, bottom = -left;
    for (int i = 0; i < balls.size(); ++i) {
        const double x = at(0, i), y = at(1, i), r = balls.radius[i];
        if (!std::isfinite(x) || !std::isfinite(y))
            continue; // a ball that flew off to infinity cannot be framed
        left = std::min(left, x - r);
        right = std::max(right, x + r);
        top = std::min(top, y - r);
        bottom = std::max(bottom, y + r);
    }
    if (!(right > left && bottom > top))
        return Camera();
    // The room the view fits things into (the same at every zoom).
    const ViewTransform view = viewTransform();
    const double margin = m_options.margin;
    const double w = std::max(1.0, view.area().width() - 2.0 * margin);
    const double h = std::max(1.0, view.area().height() - 2.0 * margin);
    Camera camera;
    camera.zoom = std::clamp(std::min(w / (right - left), h / (bottom - top)) / fittedScale(view), Camera::kMinZoom,
                             Camera::kMaxZoom);
    camera.centre = sim::Vec2(0.5 * (left + right), 0.5 * (top + bottom));
    return camera;
}

void Canvas::fitAllBalls()
{
    setFollowing(false);
    setCamera(allBallsCamera());
}

void Canvas::setFollowing(bool on)
{
    if (on == m_following)
        return;
    if (!on)
        m_options.camera = shownCamera(); // stay where the ball was
    m_following = on;
    update();
    emit cameraChanged();
}

void Canvas::wheelEvent(QWheelEvent* event)
{
    // One notch is 120 eighths of a degree; touchpads send smaller steps.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    zoomAbout(std::pow(kZoomStep, notches), event->position());
    event->accept();
}

bool Canvas::startsPan(const QMouseEvent& event) const
{
    if (event.button() == Qt::MiddleButton)
        return true;
    return event.button() == Qt::LeftButton && (event.modifiers() & Qt::ControlModifier) &&
           !grabsArrow(event.position(), event.modifiers(), ballAt(event.position()));
}

} // namespace forcelab
