#pragma once
// The balls of the live world as a table: one row per ball, one column per
// field with its unit, and a check box for a pinned ball. It reads the world every frame and edits it only
// through SettingsEditor, so every typed value is one step of the undo
// history and is checked like any other edit. Display text is rounded for
// reading; the edit role holds every digit of the double, so typing over
// it loses nothing.

#include <QAbstractTableModel>

namespace forcelab {

class SettingsEditor;
class SimulationController;

class BallTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Index, X, Y, Vx, Vy, Radius, Mass, Density, Charge, Colour, Restitution, Pinned, ColumnCount };
    /// The role the table sorts by: the number itself (the edit role is its exact text).
    static constexpr int kSortRole = Qt::UserRole;

    /// Neither is owned; both must outlive the model.
    BallTableModel(SimulationController* controller, SettingsEditor* editor, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// A typed value: one undo step through the editor. A new radius keeps
    /// the ball's density (its mass grows as r³, as a bigger ball of the same
    /// stuff would); a new mass or density keeps the radius. An empty
    /// restitution gives the ball the world's again; the pinned column is a
    /// check box (Qt::CheckStateRole). False when the editor refused it (it
    /// said why).
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    /// The mass of a ball of `radius` px and `density` (mass units per px³ × 3/(4π)),
    /// i.e. density × sphereMass(radius).
    static double massOf(double radius, double density);

    /// The unit of a column as the world has it ("px", "px/s", "mass"; empty
    /// for pure numbers): the table shows it in the view's units.
    static QString pixelUnit(int column);

public slots:
    /// Reads the world again (rows added or removed: the whole table).
    void refresh();
    /// The view's units changed (SI or px): every header and number again.
    void unitsChanged();

private:
    SimulationController* m_controller; // not owned
    SettingsEditor* m_editor;           // not owned
    int m_rows = 0;
};

} // namespace forcelab
