#pragma once
// The central canvas: shows the controller's world (through WorldPainter) and
// turns pointer events into the world's PointerInput. Setters store and call
// update(); all drawing happens in paintEvent.
//
// Pointer: hovering attracts and pressing on empty space repels (when the
// lesson has pointer forces), leaving stops both. Pressing on a ball selects
// it and holds it: it follows the pointer (velocity 0) until release, then
// flies off with the pointer's velocity over the last kThrowWindowMs.
//
// View: the wheel zooms about the pointer, a drag with the middle button or
// with Ctrl held pans, and the camera can follow the selected ball
// (canvas_camera.cpp).

#include "ui/canvas/history_recorder.h"
#include "ui/drawing/camera.h"
#include "ui/drawing/trail_recorder.h"
#include "ui/drawing/view_transform.h"
#include "ui/drawing/world_painter.h"

#include "sim/world/ball_state.h"
#include "sim/world/types.h"

#include <QImage>
#include <QPainter>
#include <QPointer>
#include <QWidget>

class QMenu;

#include <deque>
#include <optional>
#include <vector>

namespace forcelab {

class SettingsEditor;
class SimulationController;
struct ScriptDeparture;

class Canvas : public QWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the canvas.
    explicit Canvas(SimulationController* controller, QWidget* parent = nullptr);

    /// The record of the past the canvas draws (paths, tops, the latest
    /// collision): its owner's (not owned; it must outlive the canvas), or
    /// until one is given, the canvas's own.
    void setHistory(HistoryRecorder* history);
    HistoryRecorder* history() const { return m_history; }

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
    /// Menus the right-click menu ends with (the window's Tools and Show,
    /// for the stage view, where the menu bar is hidden); not owned, and
    /// an empty or deleted one is left out.
    void setContextMenus(const QList<QMenu*>& menus);
    /// The keys of the lesson's tools ("1 Stopwatch"), which the start
    /// banner lists under "press Space to run".
    void setToolKeys(const QStringList& keys);
    const QStringList& toolKeys() const { return m_toolKeys; }
    /// px of free space kept around the box (10; the stage view uses 4).
    void setBoxMargin(double pixels);
    /// Arrows scaled so a typical one is readable (WorldPainter::kArrowPixels).
    void setAutoArrows(bool on);
    /// false: the arrow legend is not drawn on the canvas but sent with
    /// arrowLegendChanged (the stage bar shows it, off the box).
    void setArrowLegendCard(bool on);
    /// Without auto arrows: the lesson's arrow scales times `factor`.
    void setArrowFactor(double factor);
    /// Auto arrows keep one scale through a run (and a Reset): these make it
    /// `factor` times longer, or fix it again from the frame shown now.
    void scaleRunArrows(double factor);
    void fixRunArrowsFromNow();
    const ArrowRun& arrowRun() const { return m_arrowRun; }
    /// The theme's colours and marks (ui/window/theme.h).
    void setColors(const CanvasColors& colors);
    const CanvasColors& colors() const { return m_colors; }
    /// The painter (what its last frame drew, for tests).
    const WorldPainter& painter() const { return m_painter; }
    /// The centre of mass's recorded path (world px, oldest first).
    const std::vector<sim::Vec2>& centreOfMassPath() const { return m_history->centreOfMassPath(); }
    const PaintOptions& paintOptions() const { return m_options; }

    /// Switches the trails overlay (same as setOverlays with overlays.trails).
    void setTrailsEnabled(bool enabled);
    bool trailsEnabled() const { return m_options.overlays.trails; }
    /// Trails behind every ball (up to TrailRecorder::kMaxBalls) or the selected ball only.
    void setTrailScope(TrailRecorder::Scope scope);
    TrailRecorder::Scope trailScope() const { return m_history->trails().scope(); }
    const TrailRecorder& trails() const { return m_history->trails(); }

    /// The selected ball's (or ball 0's) most recent collision for the
    /// "impact" overlay, or an invalid view (HistoryRecorder::collisionView).
    const CollisionView& collisionView() const { return m_history->collisionView(); }

    /// The picture the canvas shows now, at its size and device pixel ratio
    /// (for screenshots).
    QImage renderImage() const;
    /// The same picture laid out for `size` (logical px) at `devicePixelRatio`.
    QImage renderImage(const QSize& size, qreal devicePixelRatio) const;

    /// The ball held by the pointer, or -1.
    int draggedBall() const { return m_drag.ball; }
    /// A thrown ball gets the pointer's mean velocity over this many ms before release.
    static constexpr qint64 kThrowWindowMs = 50;

    /// Where the live run and each of the controller's compare panes are
    /// drawn in `area` (widget px), the live run first: side by side, one
    /// above the other or two by two, whichever gives the boxes the most
    /// room. Each area has its label strip at the top. One area without panes.
    QList<QRectF> paneAreas(const QRectF& area) const;
    /// Height of a pane's label strip (px; 0 without panes).
    double paneLabelHeight() const;

    /// The current map between widget and world coordinates (letterboxed)
    /// of the live run.
    ViewTransform viewTransform() const;
    QPointF worldToWidget(const sim::Vec2& world) const;
    sim::Vec2 widgetToWorld(const QPointF& widget) const;
    /// The ball under a widget point (the topmost one drawn), or -1.
    int ballAt(const QPointF& widget) const;

    /// The camera the canvas was given or moved to (zoom, centre).
    const Camera& camera() const { return m_options.camera; }
    /// The camera the view uses now: camera(), centred on the selected ball
    /// while following it.
    Camera shownCamera() const;
    void setCamera(const Camera& camera);
    /// Zooms by `factor` about a widget point, which keeps the world point
    /// under it (about the middle while following a ball). The zoom stays in
    /// [Camera::kMinZoom, Camera::kMaxZoom].
    void zoomAbout(double factor, const QPointF& widget);
    /// Moves the view by a widget distance (the world follows the pointer);
    /// stops following.
    void panBy(const QPointF& widgetDelta);
    /// The camera that shows every ball (and at most Camera::kMaxZoom).
    Camera allBallsCamera() const;
    bool isFollowing() const { return m_following; }
    /// One wheel notch (or a zoom key) zooms by this factor.
    static constexpr double kZoomStep = 1.25;

    /// The ruler: Shift + drag on the canvas measures a distance in the
    /// world's px (and its angle); a plain click clears it. A second Shift +
    /// drag that starts at an end of the line (within kTipGrabPixels, scaled
    /// with the lines) draws a second leg from that end, and the ruler shows
    /// the angle between the legs too (two paths after a collision, lesson 29).
    struct Ruler {
        bool shown = false;
        sim::Vec2 from{0, 0}, to{0, 0}; ///< the first leg, world px
        bool hasSecond = false;         ///< a second leg from `pivot` to `end`
        bool secondFromStart = false;   ///< the second leg starts at `from` (else at `to`)
        sim::Vec2 end{0, 0};            ///< the second leg's far end, world px
        double length() const { return (to - from).norm(); }
        /// Degrees from the +x axis, counted anticlockwise as seen (y grows downwards).
        double angle() const;
        /// The end of the first leg the second starts from.
        sim::Vec2 pivot() const { return secondFromStart ? from : to; }
        double secondLength() const { return (end - pivot()).norm(); }
        /// Degrees between the two legs at the pivot, 0 to 180 (0 with no
        /// second leg or a leg of no length).
        double between() const;
    };
    const Ruler& ruler() const { return m_ruler; }
    /// The ruler's cards as drawn, in the shown units: one leg's length and
    /// direction ("3.2 m at 45°"), or both legs' lengths and the angle
    /// between them; empty when no ruler is shown.
    QStringList rulerTexts() const;
    /// Where a student's trace first departs from the run (File → Check a
    /// Student's Trace): the student's position of `ball` at `step`, drawn
    /// as a red cross joined to the ball while the world is at that step.
    struct TraceMark {
        std::int64_t step = 0;
        int ball = 0;
        sim::Vec2 student{0, 0}; ///< world px, the student's x and y there
        QString text;            ///< the card beside the cross ("student, step 1")
    };
    void setTraceMark(const std::optional<TraceMark>& mark);
    const std::optional<TraceMark>& traceMark() const { return m_traceMark; }
    /// Whether the mark is drawn now (the world is at its step).
    bool showsTraceMark() const;
    /// The words over the live run and each compare pane, in the panes'
    /// order (empty without panes): with a student's code running, the
    /// reference's and the student's energy and where the code departed.
    QStringList paneLabels() const;
    /// The tops of the flights recorded for the "apexes" overlay (world px, oldest first).
    const std::vector<ApexMark>& apexes() const { return m_history->apexes(); }

    /// Frames painted so far and the cost of the last one (for the status bar).
    qint64 framesPainted() const { return m_frames; }
    double lastPaintMs() const { return m_lastPaintMs; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    /// Whether the "press Space to run" banner is shown (paused at t = 0).
    bool showsStartHint() const;

    /// The edit path for balls changed by hand (a drag, the velocity arrow,
    /// the right-click menu, the ball actions): each edit is one undo step.
    /// Without one a drag still moves the ball, with no undo step. Not owned.
    void setEditor(SettingsEditor* editor);
    SettingsEditor* editor() const { return m_editor; }

    /// Where the tip of ball i's velocity arrow is drawn (widget px), at the
    /// scale the arrows are drawn with now.
    QPointF velocityTip(int ball) const;
    /// The ball whose velocity arrow is being dragged, or −1.
    int arrowBall() const { return m_arrow.ball; }
    /// px: a press this close to the tip of the selected ball's velocity
    /// arrow (drawn when the velocity overlay is on), and not on a ball,
    /// takes the arrow; Alt + press on any ball takes its arrow too.
    static constexpr double kTipGrabPixels = 14.0;
    /// px/s: with Ctrl held, a dragged velocity snaps to multiples of this per component.
    static constexpr double kVelocitySnap = 10.0;

    /// The right-click menu for a widget point: on a ball, edit, stop,
    /// duplicate, copy, delete and follow it; on empty space, add or paste a
    /// ball there, zoom in there or out, fit the box or all balls.
    void fillContextMenu(QMenu& menu, const QPointF& at);

    /// The ball a new one copies its size from: the selected one, or a 15 px ball.
    sim::Ball newBallTemplate() const;

public slots:
    /// Adds a ball (the size of the selected one, at rest) at a widget point;
    /// moved to touching if it would overlap. Selects it.
    void addBallAt(const QPointF& widget);
    /// Adds a ball at the middle of the box (the Add Ball action).
    void addBall();
    void deleteSelectedBall();
    void duplicateSelectedBall();
    /// Copies the selected ball to the clipboard (as a lesson file's ball).
    void copySelectedBall();
    /// Adds the ball on the clipboard at a widget point (its own place when
    /// `widget` is null).
    void pasteBallAt(const QPointF& widget);
    void pasteBall();

    void zoomIn();  ///< by kZoomStep about the middle
    void zoomOut();
    /// The whole box, as large as it fits (the view a lesson opens with).
    void fitBox();
    void fitAllBalls();
    /// Keeps the selected ball in the middle of the view while it moves.
    void setFollowing(bool on);

signals:
    /// The arrow legend's rows changed (empty: no arrows drawn); sent after
    /// the frame that drew them.
    void arrowLegendChanged(const QList<ArrowLegendRow>& rows);
    /// The camera moved or zoomed, or following started or stopped.
    void cameraChanged();
    /// "Edit" of the right-click menu: show ball `index` in the ball table.
    void editBallRequested(int index);
    void selectedBallChanged(int index);
    /// The overlays changed (by a lesson, an action or a panel).
    void overlaysChanged();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    void paintStartHint(QPainter& p) const;
    /// The live run and the compare panes into `area`.
    void paintRuns(QPainter& p, const QRectF& area, WorldPainter& live, std::vector<WorldPainter>& panes,
                   qreal dpr) const;
    /// The live run's area of the widget (below its label strip when there are panes).
    QRectF liveArea() const;
    // A press on a ball selects it and only arms a grab: the ball is taken
    // (held, then thrown or dropped) once the pointer has moved the platform's
    // drag distance, so a click never touches the physics.
    struct Press {
        int ball = -1;     // the ball under the press, or −1
        QPointF at;        // widget px
        qint64 ms = 0;     // event time
    };
    struct Drag {
        int ball = -1;
        sim::Vec2 offset{0, 0}; // ball centre minus pointer, world px
        sim::Vec2 target{0, 0}; // where the held ball is kept, world px
        std::deque<std::pair<qint64, sim::Vec2>> samples; // (event ms, pointer world px)
        sim::Ball before; // the ball when it was taken (what Undo puts back)
    };
    // A drag of a velocity arrow's tip: the ball's velocity follows the tip,
    // at the arrow scale frozen at the press.
    struct ArrowDrag {
        int ball = -1;
        sim::Ball before;       // what Undo puts back
        double scale = 0.0;     // s: arrow length per speed, frozen for the drag
        bool autoArrows = false; // the canvas's own settings, put back at the end
        double velocityScale = 0.25;
        double arrowFactor = 1.0;
    };

    void sendPointer(const QPointF& widget, bool inside, bool pressed);
    void onSceneChanged();
    void onStepped();
    void holdDraggedBall();
    void dragTo(const QPointF& widget, qint64 timestampMs);
    void startDrag(const QPointF& widget, qint64 timestampMs);
    /// The drop of a dragged ball with `velocity`: one undo step (from where
    /// it was taken) through the editor.
    void finishDrag(const Drag& drag, const sim::Vec2& velocity);
    bool grabsArrow(const QPointF& widget, Qt::KeyboardModifiers modifiers, int ballUnder) const;
    void startArrowDrag(int ball);
    void arrowTo(const QPointF& widget, Qt::KeyboardModifiers modifiers);
    void finishArrowDrag();
    void showNote(const QString& message, bool refused);
    /// The options the frame is painted with: the shown camera and the slow-motion positions.
    PaintOptions frameOptions() const;
    /// Widget px per world px of the fitted view that `view` (made with the shown camera) zooms.
    double fittedScale(const ViewTransform& view) const;
    /// A pan drag (the middle button, or Ctrl + the left button on no arrow tip).
    bool startsPan(const QMouseEvent& event) const;

    SimulationController* m_controller; // not owned
    WorldPainter m_painter;
    PaintOptions m_options;
    QList<QPointer<QMenu>> m_contextMenus; // not owned
    QStringList m_toolKeys;                // "1 Stopwatch", …
    ArrowRun m_arrowRun;                   // the arrows' scales of this run (m_options.arrowRun)
    int m_sceneSerial = -1;                // the controller's scene the run scales belong to
    Ruler m_ruler;
    std::optional<TraceMark> m_traceMark;
    void paintTraceMark(QPainter& p) const;
    static void paintStudentCross(QPainter& p, const QPointF& at, const QString& card, double k);
    void paintDeparture(QPainter& p, const QRectF& area, const sim::World& pane, const ScriptDeparture& d,
                        const PaintOptions& paneOptions) const;
    bool m_measuringSecond = false; // the drag moves the second leg's end
    bool m_measuring = false;
    void paintRuler(QPainter& p) const;
    CanvasColors m_colors;
    std::vector<WorldPainter> m_panePainters; // one per compare pane (own sprite caches and path layers)
    double m_previousTime = -1.0; // of the last frame: a held ball is put back once per step
    HistoryRecorder* m_history = nullptr; // the canvas's own (a child) or its owner's
    Drag m_drag;
    Press m_press;
    ArrowDrag m_arrow;
    SettingsEditor* m_editor = nullptr; // not owned
    QPointF m_lastPointer; // widget px, the last pointer position over the canvas (for notes)
    bool m_following = false;   // the camera follows the selected ball
    bool m_panning = false;     // a pan drag is under way
    QPointF m_panFrom;          // widget px, the pointer at the last pan move
    qint64 m_frames = 0;
    QList<ArrowLegendRow> m_arrowLegend; // as last sent with arrowLegendChanged
    double m_lastPaintMs = 0.0;
};

} // namespace forcelab
