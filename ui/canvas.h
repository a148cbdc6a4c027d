#pragma once
// The central canvas: shows the controller's world (through WorldPainter) and
// turns pointer events into the world's PointerInput. Setters store and call
// update(); all drawing happens in paintEvent.

#include "view_transform.h"
#include "world_painter.h"

#include "sim/types.h"

#include <QWidget>

namespace forcelab {

class SimulationController;

class Canvas : public QWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the canvas.
    explicit Canvas(SimulationController* controller, QWidget* parent = nullptr);

    void setOverlays(const Overlays& overlays);
    const Overlays& overlays() const { return m_options.overlays; }
    /// The ball the readout and arrows describe; -1 for none.
    void setSelectedBall(int index);
    int selectedBall() const { return m_options.selected; }
    /// Colour of balls touching another ball (when the "colliding" overlay is on).
    void setMarkedColor(const QColor& color);
    QColor markedColor() const;
    /// Thicker lines and larger text (presentation mode).
    void setLineScale(double scale);
    const PaintOptions& paintOptions() const { return m_options; }

    /// The current map between widget and world coordinates (letterboxed).
    ViewTransform viewTransform() const;
    QPointF worldToWidget(const sim::Vec2& world) const;
    sim::Vec2 widgetToWorld(const QPointF& widget) const;
    /// The ball under a widget point (the topmost one drawn), or -1.
    int ballAt(const QPointF& widget) const;

    /// Frames painted so far and the cost of the last one (for the status bar).
    qint64 framesPainted() const { return m_frames; }
    double lastPaintMs() const { return m_lastPaintMs; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void selectedBallChanged(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void sendPointer(const QPointF& widget, bool inside, bool pressed);
    void onSceneChanged();

    SimulationController* m_controller; // not owned
    WorldPainter m_painter;
    PaintOptions m_options;
    qint64 m_frames = 0;
    double m_lastPaintMs = 0.0;
};

} // namespace forcelab
