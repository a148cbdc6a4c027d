#pragma once
// Energy bars: the world's energy now as four bars a class reads like a
// bank account — kinetic, potential, lost (to drag, inelastic impacts and
// walls since the energy books started) and their total. With nothing added
// by hand or wind, the total stays where it started; what the integrator
// gets wrong is the only change in it.
//
// A self-contained widget (the Plots dock shows it as a tab; the stage can
// show it beside the box): it follows its SimulationController, redraws at
// most every kRedrawMs and only while shown, and keeps the world's energy
// books on (SimulationController::holdAccounting) while it is shown.

#include <QChartView>
#include <QPointer>
#include <QTimer>

class QBarSet;
class QBarCategoryAxis;
class QValueAxis;

namespace forcelab {

namespace sim {
class World;
}

class SimulationController;

class EnergyBars : public QChartView {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the widget.
    explicit EnergyBars(SimulationController* controller, QWidget* parent = nullptr);
    ~EnergyBars() override;

    static constexpr int kRedrawMs = 100;

    enum class Bar { Kinetic, Potential, Lost, Total };

    /// The energies of a world, mass·px²/s² (mass · (px/s)²).
    struct Account {
        double kinetic = 0.0;   ///< ½ Σ m v²
        double potential = 0.0; ///< as sim::World::energy() counts it (gravity, springs, attraction …)
        /// −(energy booked on purpose since the books started): taken out by
        /// drag, impacts and walls (+), put in by wind, the hand or an edit
        /// (−). 0 when the world keeps no books (lostKnown false).
        double lost = 0.0;
        bool lostKnown = false;
        double total = 0.0; ///< kinetic + potential + lost
        double value(Bar bar) const;
    };
    static Account accountOf(const sim::World& world);

    /// What the bars show now (as of the last refresh).
    const Account& shown() const { return m_shown; }
    /// The common factor divided out of the bar heights; the axis title names it.
    double shownFactor() const { return m_factor; }
    /// The bar of one quantity (one set per bar, so each has its own colour);
    /// its value at index int(bar) is the height drawn, in units of shownFactor().
    QBarSet* barSet(Bar bar) const;
    QValueAxis* valueAxis() const { return m_valueAxis; }
    QBarCategoryAxis* categoryAxis() const { return m_categoryAxis; }

public slots:
    /// Redraws the bars from the world now (the timer calls it).
    void refresh();

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void scheduleRefresh();

    // Not owned; a QPointer because the window deletes its controller,
    // made first, before the docks that hold this chart.
    QPointer<SimulationController> m_controller;
    QTimer m_redraw;
    Account m_shown;
    double m_factor = 1.0;
    QBarSet* m_sets[4] = {};
    QBarCategoryAxis* m_categoryAxis = nullptr;
    QValueAxis* m_valueAxis = nullptr;
};

} // namespace forcelab
