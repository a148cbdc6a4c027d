#pragma once
// The title bar of a tool panel floating over the stage: its name and a
// close button, drawn by Qt itself. Without a window manager (a projector
// PC that runs only ForceLab, or the bare X server of the tests) a floating
// panel gets no frame from the system, so it could be neither moved nor
// closed with the mouse; with this bar it is moved by dragging the bar.

#include <QWidget>

class QDockWidget;
class QLabel;

namespace forcelab {

class StageToolTitle : public QWidget {
    Q_OBJECT
public:
    explicit StageToolTitle(QDockWidget* dock);

    /// Gives `dock` this bar while it floats on the stage (once).
    static void attach(QDockWidget* dock);
    /// Takes the bar away again: the panel docks with its usual title.
    static void detach(QDockWidget* dock);

protected:
    void changeEvent(QEvent* event) override;

private:
    QLabel* m_title = nullptr;
};

} // namespace forcelab
