#pragma once
// What the stage draws, as the user's choice: one checkable action per
// drawing aid (velocity and force arrows, paths, readout, totals, grid,
// markers) and "arrows of a readable length". The lesson's overlays are the
// default; a lesson change puts them back. The View menu and the toolbar's
// "Show" button share these actions.

#include <QList>
#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace forcelab {

class Canvas;
struct Overlays;

class OverlayActions : public QObject {
    Q_OBJECT
public:
    OverlayActions(Canvas* canvas, QWidget* parent);

    /// The "Show" menu with every action.
    QMenu* menu() const { return m_menu; }
    /// The actions' checks follow the canvas (after a lesson set its overlays).
    void sync();
    /// The factors the Arrow length menu offers besides auto.
    static constexpr double kArrowFactors[] = {0.25, 0.5, 1.0, 2.0, 4.0};

private:
    void add(const QString& name, const QString& text, bool Overlays::*member);

    Canvas* m_canvas; // not owned
    QMenu* m_menu = nullptr;
    QList<QPair<QAction*, bool Overlays::*>> m_actions;
    QAction* m_autoArrows = nullptr;
};

} // namespace forcelab
