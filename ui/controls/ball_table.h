#pragma once
// Every ball of the world in a table (position, velocity, radius, mass,
// density, charge, colour, with units), editable and sortable, with buttons
// to add, duplicate and delete, and a line for what the last edit did. The
// Balls dock holds one and the stage view another; the selection of each
// follows the canvas's and the canvas follows it.

#include <QWidget>

class QAction;
class QLabel;
class QSortFilterProxyModel;
class QTableView;

namespace forcelab {

class BallTableModel;
class SettingsEditor;
class SimulationController;

class BallTable : public QWidget {
    Q_OBJECT
public:
    /// `controller` and `editor` are not owned and must outlive the dock.
    /// The actions (add, duplicate, delete) are placed as its buttons.
    BallTable(SimulationController* controller, SettingsEditor* editor, const QList<QAction*>& actions,
              QWidget* parent = nullptr);

    QTableView* view() const { return m_view; }
    BallTableModel* model() const { return m_model; }
    /// The table's row of ball `ball` (sorted order), or −1.
    int rowOf(int ball) const;

public slots:
    /// Selects ball `index`'s row (−1: none) and scrolls to it.
    void setSelectedBall(int index);

signals:
    /// The user selected a ball in the table.
    void ballSelected(int index);

private:
    BallTableModel* m_model;
    QSortFilterProxyModel* m_proxy;
    QTableView* m_view;
    QLabel* m_note;
    int m_selected = -1;
    bool m_selecting = false; // the dock itself is selecting: do not echo
};

} // namespace forcelab
