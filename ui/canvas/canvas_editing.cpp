// The canvas as an editor of balls: the drop of a dragged ball, the drag of a
// velocity arrow's tip, the right-click menu and the ball actions. Every edit
// goes through the SettingsEditor, so it is one undo step and is checked
// (ranges, walls, overlap) like a typed value.

#include "ui/canvas/canvas.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/ball_clipboard.h"
#include "ui/controls/ball_commands.h"
#include "ui/controls/settings_editor.h"

#include "sim/world/scene.h"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QMenu>

#include <utility>
#include <QToolTip>

#include <cmath>

namespace forcelab {

void Canvas::setEditor(SettingsEditor* editor)
{
    if (m_editor)
        disconnect(m_editor, nullptr, this, nullptr);
    m_editor = editor;
    if (m_editor)
        connect(m_editor, &SettingsEditor::ballEditNote, this, &Canvas::showNote);
}

void Canvas::showNote(const QString& message, bool refused)
{
    // At the pointer, where the class is looking (only when the canvas is shown).
    if (!isVisible())
        return;
    const QPointF at = rect().contains(m_lastPointer.toPoint()) ? m_lastPointer : QPointF(width() / 2.0, height() / 2.0);
    QToolTip::showText(mapToGlobal(at.toPoint()), refused ? tr("⚠ %1").arg(message) : message, this);
}

QPointF Canvas::velocityTip(int ball) const
{
    const sim::World& world = m_controller->world();
    if (ball < 0 || ball >= world.balls().size())
        return {};
    const ViewTransform view = viewTransform();
    const double scale = m_arrow.ball >= 0 ? m_arrow.scale
                                           : WorldPainter::arrowScales(world, view, m_options, nullptr).velocity;
    const sim::Vec2 x = world.balls().position.col(ball);
    return view.toWidget(sim::Vec2(x + scale * world.balls().velocity.col(ball)));
}

bool Canvas::grabsArrow(const QPointF& widget, Qt::KeyboardModifiers modifiers, int ballUnder) const
{
    if ((modifiers & Qt::AltModifier) && ballUnder >= 0)
        return true;
    // A press on a ball moves the ball (a ball at rest has its tip at its centre).
    if (!m_options.overlays.velocity || m_options.selected < 0 || ballUnder >= 0)
        return false;
    const QPointF d = widget - velocityTip(m_options.selected);
    return std::hypot(d.x(), d.y()) <= kTipGrabPixels;
}

void Canvas::startArrowDrag(int ball)
{
    const sim::World& world = m_controller->world();
    if (ball < 0 || ball >= world.balls().size())
        return;
    setSelectedBall(ball);
    m_arrow.ball = ball;
    m_arrow.before = world.balls().ball(ball);
    m_arrow.scale = WorldPainter::arrowScales(world, viewTransform(), m_options, nullptr).velocity;
    // The arrows keep this scale until the drop, so the tip stays under the
    // pointer (automatic arrows would rescale with every new speed).
    m_arrow.autoArrows = m_options.autoArrows;
    m_arrow.velocityScale = m_options.velocityScale;
    m_arrow.arrowFactor = m_options.arrowFactor;
    m_options.autoArrows = false;
    m_options.arrowFactor = 1.0;
    m_options.velocityScale = m_arrow.scale;
    sendPointer(QPointF(), false, false); // the hand holds the arrow: no pointer forces meanwhile
}

void Canvas::arrowTo(const QPointF& widget, Qt::KeyboardModifiers modifiers)
{
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (m_arrow.ball < 0 || m_arrow.ball >= balls.size() || !(m_arrow.scale > 0.0))
        return;
    const sim::Vec2 tip = widgetToWorld(widget);
    sim::Vec2 v = (tip - sim::Vec2(balls.position.col(m_arrow.ball))) / m_arrow.scale;
    if (modifiers & Qt::ControlModifier) // round values: whole tens of px/s
        v = (v / kVelocitySnap).array().round() * kVelocitySnap;
    balls.velocity.col(m_arrow.ball) = v;
    m_history->forgetVelocities(); // the hand changed a velocity: no collision "before" from it
    m_controller->notifyBallsChanged();
}

void Canvas::finishArrowDrag()
{
    const ArrowDrag arrow = m_arrow;
    m_arrow = ArrowDrag();
    m_options.autoArrows = arrow.autoArrows;
    m_options.velocityScale = arrow.velocityScale;
    m_options.arrowFactor = arrow.arrowFactor;
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (arrow.ball >= balls.size())
        return;
    sim::Ball after = balls.ball(arrow.ball);
    // The edit is made from the state before the drag, so Undo puts it back.
    writeBallFields(balls, arrow.ball, arrow.before, kBallVelocity);
    if (!m_editor || !m_editor->editBall(tr("Set the velocity of ball %1").arg(arrow.ball), arrow.ball, after,
                                         kBallVelocity)) {
        if (!m_editor) // no undo history: the drag stands
            writeBallFields(balls, arrow.ball, after, kBallVelocity);
        m_controller->notifyBallsChanged();
    }
    update();
}

void Canvas::finishDrag(const Drag& drag, const sim::Vec2& velocity)
{
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (drag.ball < 0 || drag.ball >= balls.size())
        return;
    m_history->forgetVelocities(); // the hand changed a velocity: no collision "before" from it
    sim::Ball after = balls.ball(drag.ball);
    after.velocity = velocity;
    if (!m_editor) {
        writeBallFields(balls, drag.ball, after, kBallVelocity);
        m_controller->notifyBallsChanged();
        return;
    }
    // From where it was taken to where it was dropped, as one undo step; a
    // drop over another ball or a wall is moved to touching or refused (the
    // ball then goes back to where it was taken).
    writeBallFields(balls, drag.ball, drag.before, kBallPosition | kBallVelocity);
    if (!m_editor->editBall(tr("Move ball %1").arg(drag.ball), drag.ball, after, kBallPosition | kBallVelocity))
        m_controller->notifyBallsChanged();
}

sim::Ball Canvas::newBallTemplate() const
{
    const sim::BallState& balls = m_controller->world().balls();
    sim::Ball ball;
    ball.radius = 15.0;
    if (m_options.selected >= 0 && m_options.selected < balls.size()) {
        ball.radius = balls.radius[m_options.selected];
        ball.charge = balls.charge[m_options.selected];
    }
    const std::vector<sim::Rgb>& palette = sim::defaultPalette();
    ball.color = palette[static_cast<std::size_t>(balls.size()) % palette.size()];
    ball.mass = sim::sphereMass(ball.radius);
    return ball;
}

void Canvas::addBallAt(const QPointF& widget)
{
    if (!m_editor)
        return;
    sim::Ball ball = newBallTemplate();
    ball.position = widgetToWorld(widget);
    ball.home = ball.position;
    m_lastPointer = widget;
    const int index = m_editor->addBall(tr("Add a ball"), ball);
    if (index >= 0)
        setSelectedBall(index);
}

void Canvas::addBall()
{
    const sim::BoxSettings& box = m_controller->world().settings().box;
    addBallAt(worldToWidget(sim::Vec2(0.5 * box.width, 0.5 * box.height)));
}

void Canvas::deleteSelectedBall()
{
    const int ball = m_options.selected;
    if (!m_editor || ball < 0)
        return;
    setSelectedBall(-1);
    m_editor->removeBall(ball);
}

void Canvas::duplicateSelectedBall()
{
    if (!m_editor || m_options.selected < 0)
        return;
    const int copy = m_editor->duplicateBall(m_options.selected);
    if (copy >= 0)
        setSelectedBall(copy);
}

void Canvas::copySelectedBall()
{
    const sim::BallState& balls = m_controller->world().balls();
    if (m_options.selected < 0 || m_options.selected >= balls.size())
        return;
    QApplication::clipboard()->setText(ballToText(balls.ball(m_options.selected)));
}

void Canvas::pasteBallAt(const QPointF& widget)
{
    if (!m_editor)
        return;
    QString why;
    std::optional<sim::Ball> ball = ballFromText(QApplication::clipboard()->text(), &why);
    if (!ball) {
        showNote(tr("Nothing to paste: %1").arg(why), true);
        return;
    }
    if (!widget.isNull()) {
        ball->position = widgetToWorld(widget);
        m_lastPointer = widget;
    }
    const int index = m_editor->addBall(tr("Paste a ball"), *ball);
    if (index >= 0)
        setSelectedBall(index);
}

void Canvas::pasteBall()
{
    pasteBallAt(QPointF());
}

void Canvas::fillContextMenu(QMenu& menu, const QPointF& at)
{
    m_lastPointer = at;
    const int ball = ballAt(at);
    const bool editable = m_editor != nullptr;
    if (ball >= 0) {
        setSelectedBall(ball);
        menu.addSection(tr("Ball %1").arg(ball));
        menu.addAction(tr("Edit its numbers…"), this, [this, ball] { emit editBallRequested(ball); });
        menu.addAction(tr("Stop it (v = 0)"), this, [this, ball] {
            if (ball >= m_controller->world().balls().size())
                return;
            sim::Ball still = m_controller->world().balls().ball(ball);
            still.velocity.setZero();
            m_editor->editBall(tr("Stop ball %1").arg(ball), ball, still, kBallVelocity);
        })->setEnabled(editable);
        // Pinned: nothing moves it, and balls bounce off it (one undo step).
        QAction* pin = menu.addAction(tr("Pin"), this, [this, ball](bool on) {
            if (ball >= m_controller->world().balls().size())
                return;
            sim::Ball pinned = m_controller->world().balls().ball(ball);
            pinned.pinned = on;
            m_editor->editBall(on ? tr("Pin ball %1").arg(ball) : tr("Free ball %1").arg(ball), ball, pinned,
                               kBallPinned);
        });
        pin->setCheckable(true);
        pin->setChecked(m_controller->world().balls().pinned[static_cast<std::size_t>(ball)] != 0);
        pin->setEnabled(editable);
        menu.addAction(tr("Duplicate"), this, &Canvas::duplicateSelectedBall)->setEnabled(editable);
        menu.addAction(tr("Copy"), this, &Canvas::copySelectedBall);
        menu.addSeparator();
        menu.addAction(tr("Delete"), this, &Canvas::deleteSelectedBall)->setEnabled(editable);
        menu.addSeparator();
        QAction* follow = menu.addAction(tr("Follow it"), this, [this](bool on) { setFollowing(on); });
        follow->setCheckable(true);
        follow->setChecked(m_following);
    } else {
        menu.addAction(tr("Add a ball here"), this, [this, at] { addBallAt(at); })->setEnabled(editable);
        const bool pasteable = ballFromText(QApplication::clipboard()->text()).has_value();
        menu.addAction(tr("Paste the copied ball here"), this, [this, at] { pasteBallAt(at); })
            ->setEnabled(editable && pasteable);
        // The view, for the stage view where there is no menu bar.
        menu.addSeparator();
        menu.addAction(tr("Zoom in here"), this, [this, at] { zoomAbout(kZoomStep, at); })
            ->setEnabled(camera().zoom < Camera::kMaxZoom);
        menu.addAction(tr("Zoom out"), this, [this, at] { zoomAbout(1.0 / kZoomStep, at); })
            ->setEnabled(camera().zoom > Camera::kMinZoom);
        menu.addAction(tr("Fit the box"), this, &Canvas::fitBox);
        menu.addAction(tr("Fit all balls"), this, &Canvas::fitAllBalls);
    }
    bool separated = false;
    for (const QPointer<QMenu>& extra : m_contextMenus) {
        if (!extra || extra->isEmpty())
            continue;
        if (!std::exchange(separated, true))
            menu.addSeparator();
        menu.addMenu(extra);
    }
}

void Canvas::setContextMenus(const QList<QMenu*>& menus)
{
    m_contextMenus.clear();
    for (QMenu* m : menus)
        m_contextMenus << m;
}

void Canvas::contextMenuEvent(QContextMenuEvent* event)
{
    QMenu menu(this);
    fillContextMenu(menu, event->pos());
    menu.exec(event->globalPos());
}

} // namespace forcelab
