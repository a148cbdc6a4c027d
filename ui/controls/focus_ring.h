#pragma once
// A clear ring round the control that has the keyboard focus, so a class
// (and a keyboard user) sees where the keys go, in the plain and the
// projector theme alike: Qt's own focus frame is a thin line that the back
// row cannot see. The ring is a child of the window drawn over everything,
// lets the mouse through, and follows the focus, its control's moves and
// resizes (and its parents': a scrolled panel). When the keys take the
// focus into a panel stacked behind another, that panel comes forward, so
// the focus is never on a control nobody can see. It is not drawn round the canvas (the canvas has the keys most of
// the time; the stage itself shows what they do).
#include <QList>
#include <QPointer>
#include <QWidget>

namespace forcelab {

class FocusRing : public QWidget {
    Q_OBJECT
public:
    explicit FocusRing(QWidget* window);
    /// The control the ring is round now (null: none shown).
    QWidget* target() const { return m_target; }
    static constexpr int kWidth = 3; ///< px, the ring's line

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;

private:
    void follow(QWidget* now);
    void place();

    QPointer<QWidget> m_target;
    QList<QPointer<QWidget>> m_watched; // the target and its parents: a move of any moves the ring
};

} // namespace forcelab
