#pragma once
// The arrow legend in the stage bar: for each kind of arrow the canvas
// draws, a sample arrow as long as it is on the canvas and the round
// quantity it stands for ("100 px/s (velocity)"). On the stage the legend
// lives here, so it never covers the box.

#include "ui/drawing/world_painter.h"

#include <QList>
#include <QWidget>

namespace forcelab {

class ArrowLegendView : public QWidget {
    Q_OBJECT
public:
    explicit ArrowLegendView(QWidget* parent = nullptr);

    /// The rows to show; none hides the view.
    void setRows(const QList<ArrowLegendRow>& rows);
    const QList<ArrowLegendRow>& rows() const { return m_rows; }
    /// Whether there is anything to show (the view may still be hidden by its bar).
    bool hasRows() const { return !m_rows.isEmpty(); }

    QSize sizeHint() const override;
    /// As tall as sizeHint; narrower, down to the arrows and a few words
    /// (the words then shrink to fit).
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    double padding() const;
    double widestArrow() const;

    QList<ArrowLegendRow> m_rows;
};

} // namespace forcelab
