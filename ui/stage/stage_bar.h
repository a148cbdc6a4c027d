#pragma once
// The projector stage's own controls: the lesson's title and current
// challenge as a caption, and large buttons for run/pause, step, reset,
// slower and faster (the main window's actions). The stage view puts the bar
// where the box leaves room: a column beside a wide window's box, a row under
// a tall one, so the box keeps the most of the screen.

#include <QFont>
#include <QList>
#include <QSize>
#include <QStringList>
#include <QWidget>

class QAction;
class QBoxLayout;
class QGridLayout;
class QLabel;
class QToolButton;

namespace forcelab {

class ArrowLegendView;
struct ArrowLegendRow;

class StageBar : public QWidget {
    Q_OBJECT
public:
    explicit StageBar(const QList<QAction*>& transport, QWidget* parent = nullptr);

    /// The caption: the lesson's title and the challenge to show.
    void setCaption(const QString& title, const QString& challenge);
    /// A column (beside the box) or a row (under it).
    void setVertical(bool vertical);
    /// The readout and totals the lesson shows, as text in the bar (the
    /// stage view keeps the box free of panels); empty hides it.
    void setReadout(const QString& text);
    bool isVertical() const { return m_vertical; }
    /// Whether `text` fits the readout's room at three quarters of the
    /// readout's own size or more (true while the room is not known yet): a
    /// row's readout then keeps its long lines, else it gets short ones.
    bool readoutFits(const QString& text) const;
    /// The size `text` would be set at in the readout's room (its own size
    /// while the room is not known yet).
    double readoutPointSize(const QString& text) const;
    /// The arrow legend (what a sample arrow on the box stands for): under
    /// the readout in a column, under the buttons in a row; none hides it.
    void setArrowLegend(const QList<ArrowLegendRow>& rows);
    const ArrowLegendView* arrowLegend() const { return m_legend; }
    /// The lesson's sliders (StageSliders), under the buttons; not owned before, owned after.
    void setSliders(QWidget* sliders);
    /// Shows or hides the sliders' area (a row bar without room for them).
    void setSlidersShown(bool shown);
    /// The challenge at its own size again, so that sizeHint() does not
    /// depend on how the last room fitted it; it is fitted again at once.
    void unfitChallenge();
    /// The size the challenge's text starts at, in pixels, when larger than
    /// the bar's own (the stage sets it from the screen's height); it comes
    /// down from there only to fit the bar.
    void setTextFloor(double pixels);
    /// A row bar's buttons in one row or two (two free width for the
    /// caption, at the cost of height); a column always has two across.
    void setButtonRows(int rows);
    int buttonRows() const { return m_buttonRows; }
    /// The height a row bar `width` px wide needs to show its title, the
    /// whole challenge and the readout at their starting sizes (the floor),
    /// with the buttons in `rows` rows; the sliders not counted.
    int rowHeightAtFloor(int width, int rows) const;
    /// The width a column needs to show the lines of `readout` at their
    /// starting size (the floor) and two buttons across.
    int columnWidthAtFloor(const QString& readout) const;
    /// Whether a fit of the readout or the challenge waits in the event
    /// queue (the bar has not settled on its last room yet).
    bool isFitPending() const { return m_fitQueued; }

signals:
    /// The readout's room changed size: its text may want the other form.
    void readoutRoomChanged();

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void applyFonts();
    double pointsOfPixels(double pixels) const;
    void scheduleFit();
    void fitReadout();
    void sizeReadoutColumn(const QStringList& lines);
    void fitChallenge();
    void stretchColumnRows();
    int rowButtonsWidth(int rows, bool withLegend = true) const;
    int rowButtonsHeight(int rows) const;
    QSize rowReadoutAtFloor(int free) const;
    bool legendUnderReadout(int width, int rows) const;

    QLabel* m_title = nullptr;
    QLabel* m_challenge = nullptr;
    QLabel* m_readout = nullptr;
    ArrowLegendView* m_legend = nullptr;
    QWidget* m_sliders = nullptr;
    QString m_readoutText;   // the readout's lines (the label may show them in text columns)
    QFont m_readoutFont;     // the readout's own size, before fitting
    QSize m_readoutRoom;     // the readout's room when it was last fitted
    // What the last fit of the readout depended on, and what it found.
    struct FitKey {
        QString shape; // the readout with every digit as 0
        QSize room, bar;
        QString challenge;
        bool vertical = true, hidden = true;
        int buttons = 0; // shown
        int buttonRows = 1;
        bool operator==(const FitKey&) const = default;
    };
    FitKey m_fitKey;
    QFont m_fitFont;
    int m_fitColumns = 1;
    int m_readoutColumn = 0; // px, a row's readout column (0: not set)
    QFont m_challengeFont;   // the challenge's own size, before fitting
    QString m_challengeText; // the whole challenge (the label may show it shortened)
    QList<QToolButton*> m_buttons;
    QGridLayout* m_grid = nullptr;
    bool m_vertical = true;
    int m_buttonRows = 1; // a row bar's rows of buttons
    bool m_legendUnderReadout = false; // a row's arrow legend is under its readout, not its buttons
    double m_textFloor = 0.0; // px, setTextFloor
    bool m_fitQueued = false; // scheduleFit's call waits in the event queue
};

} // namespace forcelab
