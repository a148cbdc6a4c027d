#pragma once
// What the simulation did, kept for the pictures that show the past: each
// ball's path (trails, also the compare panes'), the centre of mass's path,
// the tops of the flights and the selected ball's latest collision. Recorded
// once per frame from the controller's step signal, only for what the
// overlays show, and started over with every new scene. The canvas reads it;
// a graph or a path tool can read the same record.

#include "ui/drawing/trail_recorder.h"
#include "ui/drawing/world_painter.h"

#include "sim/world/types.h"

#include <QObject>

#include <utility>
#include <vector>

namespace forcelab {

class SimulationController;

class HistoryRecorder : public QObject {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the recorder.
    explicit HistoryRecorder(SimulationController* controller, QObject* parent = nullptr);

    /// What to record: the trails, centreOfMass, apexes and impact overlays.
    /// A record starts (empty, then the present state) when it is switched on.
    void setRecorded(const Overlays& overlays);
    /// The ball whose trail (with Scope::Selected) and collision are kept; -1 for none.
    void setSelectedBall(int index);
    /// Trails behind every ball (up to TrailRecorder::kMaxBalls) or the selected ball only.
    void setTrailScope(TrailRecorder::Scope scope);

    /// Starts every record over (balls were added or removed by hand, so the
    /// balls' indices no longer match the paths recorded).
    void startOver() { clear(); }

    /// The hand changed a velocity: the next collision has no "before" from it.
    void forgetVelocities() { m_previousVelocity.resize(0, 0); }

    const TrailRecorder& trails() const { return m_trails; }
    /// The compare panes' trails, one per pane (empty ones for panes without a world).
    const std::vector<TrailRecorder>& paneTrails() const { return m_paneTrails; }
    /// The centre of mass's path (world px, oldest first).
    const std::vector<sim::Vec2>& centreOfMassPath() const { return m_centreOfMassPath; }
    /// The tops of the flights (world px, oldest first).
    const std::vector<ApexMark>& apexes() const { return m_apexes; }
    /// The selected ball's (or, with none selected, ball 0's) most recent
    /// collision, or an invalid view. "Before" is the state at the end of the
    /// previous frame, so it is exactly the state before the step when a frame
    /// takes one step (a new contact, not one lasting from the frame before).
    const CollisionView& collisionView() const { return m_collision; }

    /// Points the centre-of-mass path keeps at most (then the older half goes).
    static constexpr std::size_t kMaxCentrePoints = 4000;
    /// Balls whose tops are marked (the first ones of the world).
    static constexpr int kMaxApexBalls = 50;

signals:
    /// Something was recorded or cleared.
    void changed();

private:
    void record();
    void clear();
    void recordCentreOfMass();
    void recordApexes();
    void trackCollision();
    void resetCollision();
    void showSelectedCollision();

    SimulationController* m_controller; // not owned
    Overlays m_recorded;
    int m_selected = -1;
    TrailRecorder m_trails;
    std::vector<TrailRecorder> m_paneTrails;
    std::vector<sim::Vec2> m_centreOfMassPath;
    std::vector<ApexMark> m_apexes;
    sim::VectorX m_apexVy; // each watched ball's vy at the last frame (px/s)
    CollisionView m_collision;
    sim::Matrix2X m_previousVelocity; // end of the previous frame (impact only)
    double m_previousTime = -1.0;
    std::vector<CollisionView> m_latest;                // each ball's latest collision (a is that ball)
    std::vector<std::pair<int, int>> m_previousContacts; // the frame before's contacts, sorted (a < b)
};

} // namespace forcelab
