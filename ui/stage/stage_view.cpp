#include "ui/stage/stage_view.h"

#include "ui/drawing/human_number.h"

#include "lessons/lesson_markup.h"
#include "ui/canvas/canvas.h"
#include "ui/controls/ball_table.h"
#include "ui/controls/settings_editor.h"
#include "ui/canvas/history_recorder.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/stage/arrow_legend_view.h"
#include "ui/stage/stage_bar.h"
#include "ui/stage/stage_sliders.h"

#include <QAction>
#include <QBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QHeaderView>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace forcelab {

StageView::StageView(SimulationController* controller, SettingsEditor* editor, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
    , m_editor(editor)
{
    setObjectName(QStringLiteral("stageView"));
    m_canvas = new Canvas(m_controller, this);
    // The record of the past, kept here for the canvas and whatever else
    // shows it; made after the canvas so it records after the hand holds.
    m_history = new HistoryRecorder(m_controller, this);
    m_canvas->setHistory(m_history);
    m_canvas->setEditor(m_editor);
    // Balls added or removed shift the indices the paths are kept by.
    connect(m_editor, &SettingsEditor::ballCountChanged, m_history, &HistoryRecorder::startOver);
    // The banner says, above the canvas, why the simulation stopped itself.
    m_haltBanner = new QLabel(this);
    m_haltBanner->setObjectName(QStringLiteral("haltBanner"));
    m_haltBanner->setWordWrap(true);
    m_haltBanner->setStyleSheet(QStringLiteral("QLabel { background: #fde2e1; color: #7a1410; "
                                               "border-bottom: 2px solid #c0392b; padding: 8px; }"));
    m_haltBanner->hide();
    m_layout = new QBoxLayout(QBoxLayout::LeftToRight, this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(0);
    auto* column = new QVBoxLayout;
    column->setSpacing(0);
    column->addWidget(m_haltBanner);
    column->addWidget(m_canvas, 1);
    // The ball table under the box in the stage view (the Balls button).
    m_ballTable = new BallTable(m_controller, m_editor, {}, this);
    m_ballTable->hide();
    column->addWidget(m_ballTable);
    connect(m_canvas, &Canvas::selectedBallChanged, m_ballTable, &BallTable::setSelectedBall);
    connect(m_ballTable, &BallTable::ballSelected, m_canvas, &Canvas::setSelectedBall);
    m_layout->addLayout(column, 1);
    connect(m_controller, &SimulationController::haltedChanged, this, &StageView::showHalted);
}

void StageView::createBar(const QList<QAction*>& actions)
{
    // The row bar under the box has room for the lesson's sliders only on a
    // wide screen; on a 4:3 projector this button makes the bar taller to
    // show them (the box shrinks while they are shown).
    m_slidersAction = new QAction(style()->standardIcon(QStyle::SP_FileDialogDetailedView), tr("Sliders"), this);
    m_slidersAction->setObjectName(QStringLiteral("stageSlidersAction"));
    m_slidersAction->setCheckable(true);
    m_slidersAction->setShortcut(Qt::Key_S);
    m_slidersAction->setStatusTip(tr("Show the lesson's sliders under the box in the stage view (S)"));
    m_slidersAction->setVisible(false);
    connect(m_slidersAction, &QAction::toggled, this, &StageView::layoutStage);

    m_ballsAction = new QAction(style()->standardIcon(QStyle::SP_FileDialogListView), tr("Balls"), this);
    m_ballsAction->setObjectName(QStringLiteral("stageBallsAction"));
    m_ballsAction->setCheckable(true);
    m_ballsAction->setShortcut(Qt::Key_T);
    m_ballsAction->setStatusTip(tr("Show every ball's numbers under the box, to type new ones (T)"));
    connect(m_ballsAction, &QAction::toggled, this, [this](bool on) {
        m_ballTable->setVisible(on && isStaged());
        layoutStage();
    });
    // Read from the back of the room: the table's text as large as the sliders'.
    QFont large = m_ballTable->font();
    large.setPointSizeF(large.pointSizeF() * 1.35);
    m_ballTable->setFont(large);
    m_ballTable->view()->horizontalHeader()->setFont(large);

    m_bar = new StageBar(QList<QAction*>(actions) << m_ballsAction << m_slidersAction, this);
    m_layout->addWidget(m_bar);
    m_bar->hide();
    m_sliders = new StageSliders(m_controller, m_editor, m_bar);
    m_bar->setSliders(m_sliders);
    connect(m_controller, &SimulationController::stepped, this, &StageView::updateReadout);
    // The clock line shows the speed, also while paused (the Play button
    // says whether it runs).
    connect(m_controller, &SimulationController::timeScaleChanged, this, &StageView::updateReadout);
    connect(m_controller, &SimulationController::sceneChanged, this, &StageView::updateReadout);
    connect(m_controller, &SimulationController::seeked, this, &StageView::updateReadout);
    connect(m_bar, &StageBar::readoutRoomChanged, this, &StageView::updateReadout, Qt::QueuedConnection);
    // The arrow legend goes to the bar; the bar is laid out again when it
    // gains or loses a row (its height), not for every new arrow length.
    connect(m_canvas, &Canvas::arrowLegendChanged, this, [this](const QList<ArrowLegendRow>& rows) {
        const qsizetype before = m_bar->arrowLegend()->isHidden() ? 0 : m_bar->arrowLegend()->rows().size();
        m_bar->setArrowLegend(rows);
        if (isStaged() && rows.size() != before) // not inside the canvas's paint event
            QMetaObject::invokeMethod(this, &StageView::layoutStage, Qt::QueuedConnection);
    });
}

void StageView::showBallTable(int index)
{
    m_ballsAction->setChecked(true);
    m_ballTable->setVisible(isStaged());
    layoutStage();
    m_ballTable->setSelectedBall(index);
    m_ballTable->view()->setFocus();
}

bool StageView::isStaged() const
{
    return m_bar && m_bar->isVisible();
}

void StageView::setStaged(bool on)
{
    if (on) {
        m_canvas->setBoxMargin(4.0);
        m_canvas->setArrowLegendCard(false); // the bar shows it, off the box
        m_canvas->setOverlays(withoutReadouts(m_canvas->overlays()));
        m_bar->setCaption(m_title, m_challenge);
        m_bar->show();
        m_ballTable->setVisible(m_ballsAction->isChecked());
        updateReadout(); // shown now, so it fills in
    } else {
        m_bar->hide();
        m_ballTable->hide(); // the window's Balls dock shows them
        m_canvas->setBoxMargin(10.0);
        m_canvas->setArrowLegendCard(true);
        Overlays back = m_canvas->overlays();
        back.readout = m_ownOverlays.readout;
        back.totals = m_ownOverlays.totals;
        m_canvas->setOverlays(back);
    }
}

void StageView::setLesson(const Lesson& lesson)
{
    m_title = lessons::markupToPlainText(lesson.title);
    m_challenge = lessons::markupToPlainText(lesson.challenges.value(0));
    m_bar->setCaption(m_title, m_challenge);
    updateReadout();
    m_sliders->setLessonControls(lesson.controls);
    layoutStage(); // the box's shape decides where the bar goes
}

void StageView::setOverlays(const Overlays& overlays)
{
    m_canvas->setOverlays(isStaged() ? withoutReadouts(overlays) : overlays);
}

void StageView::showHalted(const QString& reason)
{
    m_haltBanner->setText(tr("<b>Stopped:</b> %1").arg(reason.toHtmlEscaped()));
    m_haltBanner->setVisible(!reason.isEmpty());
}

void StageView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    layoutStage();
}

// The stage view shows the readout and the totals in its bar, not on the
// canvas: remembers which of them the canvas had, and returns the canvas's
// overlays without them.
Overlays StageView::withoutReadouts(Overlays overlays)
{
    m_ownOverlays = overlays;
    overlays.readout = overlays.totals = false;
    return overlays;
}

void StageView::updateReadout()
{
    if (!isStaged())
        return;
    // Long lines in a row, short ones in a column, and in a row too when
    // the long ones would have to shrink out of reading size or the short
    // ones, in text columns, are larger.
    const Readout text = readoutText();
    const bool wide = !m_bar->isVertical() && m_bar->readoutFits(text.wide) &&
                      m_bar->readoutPointSize(text.wide) >= m_bar->readoutPointSize(text.narrow);
    m_bar->setReadout(wide ? text.wide : text.narrow);
}

// Both forms from one evaluation of the accelerations and the energy (each
// a pass over every pair of balls when they attract); the words and numbers
// are the painter's (WorldPainter::readoutText), the one source of the
// readout's text.
StageView::Readout StageView::readoutText() const
{
    const sim::World& world = m_controller->world();
    // Always the clock and the speed first, whatever the lesson shows.
    const QString clock = clockText(world.time(), m_controller->timeScale());
    QStringList wide{clock}, narrow{clock};
    if (m_ownOverlays.readout && !world.balls().empty()) {
        const sim::Matrix2X a = world.accelerations();
        const int selected = m_canvas->selectedBall();
        wide << WorldPainter::readoutText(world, selected, &a, WorldPainter::ReadoutShape::Wide);
        narrow << WorldPainter::readoutText(world, selected, &a, WorldPainter::ReadoutShape::Short);
    }
    if (m_ownOverlays.totals) {
        const sim::Energy e = world.energy();
        const sim::Vec2 p = world.momentum();
        const double scale = WorldPainter::momentumScale(world);
        wide << WorldPainter::totalsText(e, p, true, scale);
        narrow << WorldPainter::stageTotalsText(e, p, m_bar->isVertical(), scale);
    }
    return {wide.join(QLatin1Char('\n')), narrow.join(QLatin1Char('\n'))};
}

QString StageView::clockText(double time, double timeScale)
{
    // The speeds the Slower and Faster buttons step through, as a class
    // reads them: fractions (½ and ¼ are in every projector font).
    static const std::pair<double, const char*> fractions[] = {
        {0.5, "½"}, {0.25, "¼"}, {0.125, "1/8"}, {1.0 / 16, "1/16"}, {1.0 / 32, "1/32"}, {1.0 / 64, "1/64"}};
    QString speed = humanNumber(timeScale, 3);
    for (const auto& [value, text] : fractions)
        if (std::abs(timeScale - value) < 1e-12)
            speed = QString::fromUtf8(text);
    return tr("t = %1 s   %2× speed").arg(time, 0, 'f', 2).arg(speed);
}

// In the stage view the bar takes the strip the box leaves: a column beside
// it when the window is wider than the box (16:9 screens and a 3:2 box), a
// row under it otherwise, so the box is as large as the window allows.
void StageView::layoutStage()
{
    if (!isStaged())
        return;
    // The challenge for the back row: from 2.4% of the screen's height.
    m_bar->setTextFloor(kTextFloorShare * height());
    const sim::BoxSettings& box = m_controller->world().settings().box;
    const double aspect = box.width > 0 && box.height > 0 ? box.width / box.height : 1.5;
    QSize area = size();
    if (m_ballTable->isVisibleTo(this)) {
        // The ball table takes a quarter of the height under the box (at
        // least four rows); the box and the bar share the rest.
        const int rows = std::clamp(area.height() / 4, 150, 280);
        m_ballTable->setFixedHeight(rows);
        area.rheight() -= rows;
    }
    const double side = area.width() - aspect * area.height();      // px left beside a full-height box
    const double below = area.height() - area.width() / aspect;      // px left under a full-width box
    const bool vertical = side >= below;
    const bool wasVertical = m_bar->isVertical();
    m_bar->setVertical(vertical);
    m_layout->setDirection(vertical ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    // Two sliders side by side in a column at least 320 px wide (one in a
    // narrower one, so a label such as "Ball restitution" is not cut); in a
    // row as many as fit its width.
    const int columnWidth = std::max(200, static_cast<int>(side));
    m_sliders->setColumns(vertical ? (columnWidth >= 320 ? 2 : 1)
                                        : std::clamp(area.width() / 240, 1, std::max(1, m_sliders->count())));
    int minimum = 200;
    if (!vertical) {
        // A row is as tall as the title, the whole challenge and the readout
        // need at their starting size (the floor), between a seventh and a
        // quarter of the screen (the box keeps three quarters of it at
        // least); the buttons go in two rows when that gives the caption the
        // width to need less height. Sliders that do not fit under that wait
        // for the Sliders button, which lets the bar take up to 2/5 of the
        // screen to show them.
        const int least = std::max(96, area.height() / 7);
        const int most = std::max(least, area.height() / 4);
        const bool sliders = m_sliders->count() > 0;
        m_bar->unfitChallenge(); // its size hint at its own font, whatever room it had before
        // Measured with the Sliders button in the row whenever there are
        // sliders: when they fit after all it goes, and the caption has more room.
        m_slidersAction->setVisible(sliders);
        const int oneRow = m_bar->rowHeightAtFloor(area.width(), 1);
        const int twoRows = m_bar->rowHeightAtFloor(area.width(), 2);
        m_bar->setButtonRows(oneRow <= least || oneRow <= twoRows ? 1 : 2);
        const int cap = std::clamp(std::min(oneRow, twoRows), least, most);
        const int slidersHeight = m_sliders->sizeHint().height() + 8;
        m_bar->setSlidersShown(sliders);
        // A wide box (lesson 27's 1000 × 300) leaves more than a quarter
        // under it: the sliders then use that room instead of waiting for
        // the Sliders button.
        const int room = std::max(most, static_cast<int>(below));
        const bool fit = m_bar->sizeHint().height() <= least || cap + slidersHeight <= room;
        m_slidersAction->setVisible(sliders && !fit);
        const bool asked = sliders && !fit && m_slidersAction->isChecked();
        m_bar->setSlidersShown(sliders && (fit || asked));
        if (asked) // the bar as without them, plus the rows of sliders
            minimum = std::min(cap + slidersHeight, area.height() * 2 / 5);
        else if (sliders && fit)
            minimum = std::clamp(std::max(m_bar->sizeHint().height(), cap + slidersHeight), 96, room);
        else
            minimum = cap;
    } else {
        m_slidersAction->setVisible(false);
        m_bar->setSlidersShown(m_sliders->count() > 0);
        // A column as wide as the readout's short lines need at the floor,
        // up to 22% of the width (the box keeps the rest).
        minimum = std::clamp(m_bar->columnWidthAtFloor(readoutText().narrow), 200,
                             std::max(200, area.width() * 22 / 100));
    }
    const int strip = std::max(minimum, static_cast<int>(vertical ? side : below));
    if (vertical) {
        m_bar->setFixedWidth(strip);
        m_bar->setMinimumHeight(0);
        m_bar->setMaximumHeight(QWIDGETSIZE_MAX);
    } else {
        m_bar->setFixedHeight(strip);
        m_bar->setMinimumWidth(0);
        m_bar->setMaximumWidth(QWIDGETSIZE_MAX);
    }
    if (vertical != wasVertical)
        updateReadout(); // short lines in a column, long ones in a row
}

} // namespace forcelab
