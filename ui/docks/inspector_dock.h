#pragma once
// The Inspector dock: the numbers of the selected ball, updated every frame:
// position, velocity, acceleration, mass and radius, and the force of every
// enabled model on it (F = m a per model, and their sum), as the tutorial's
// readout does. A switch draws the ball's trail.

#include "sim/world/types.h"

#include <QDockWidget>
#include <QString>

#include <vector>

class QCheckBox;
class QLabel;
class QStackedWidget;

namespace forcelab::sim {
class World;
}

namespace forcelab {

class SimulationController;

class InspectorDock : public QDockWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the dock.
    explicit InspectorDock(SimulationController* controller, QWidget* parent = nullptr);

    /// The force one model puts on the ball, m × its acceleration.
    struct ModelForce {
        QString model;  ///< "gravity", "drag", …
        sim::Vec2 force; ///< mass·px/s²
    };
    /// What the dock shows, as numbers (the labels show these).
    struct Readout {
        int ball = -1;
        sim::Vec2 position{0.0, 0.0};     ///< px
        sim::Vec2 velocity{0.0, 0.0};     ///< px/s
        sim::Vec2 acceleration{0.0, 0.0}; ///< px/s², World::accelerations()
        double mass = 0.0;
        double radius = 0.0;              ///< px
        std::vector<ModelForce> forces;   ///< one per enabled model
        sim::Vec2 totalForce{0.0, 0.0};   ///< m a
    };
    const Readout& readout() const { return m_readout; }

    /// The force of each enabled model on ball i. Models that depend only on
    /// the ball itself are evaluated on that ball alone; gravity between balls
    /// needs them all. What the public API cannot split (the random
    /// acceleration, drawn inside the world) is the rest of m a.
    static std::vector<ModelForce> modelForces(const sim::World& world, int i, const sim::Vec2& acceleration);

    int selectedBall() const { return m_readout.ball; }
    bool isTrailOn() const;

public slots:
    void setSelectedBall(int index);
    /// Reads the world again (every frame while the dock is visible).
    void refresh();

signals:
    /// The user switched the selected ball's trail on or off.
    void trailToggled(bool on);

private:
    SimulationController* m_controller; // not owned
    Readout m_readout;
    QStackedWidget* m_pages = nullptr;
    QLabel* m_ballLabel = nullptr;
    QLabel* m_positionLabel = nullptr;
    QLabel* m_velocityLabel = nullptr;
    QLabel* m_accelerationLabel = nullptr;
    QLabel* m_massLabel = nullptr;
    QLabel* m_forcesLabel = nullptr;
    QCheckBox* m_trailCheck = nullptr;
};

} // namespace forcelab
