#include "stage_bar.h"

#include <QAction>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QScrollArea>
#include <QTimer>
#include <QToolButton>

#include <algorithm>

namespace forcelab {

StageBar::StageBar(const QList<QAction*>& transport, QWidget* parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("stageBar"));
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, QColor(0x1d, 0x22, 0x2c));
    p.setColor(QPalette::WindowText, Qt::white);
    setPalette(p);
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("stageTitle"));
    m_title->setWordWrap(true);
    m_challenge = new QLabel(this);
    m_challenge->setObjectName(QStringLiteral("stageChallenge"));
    m_challenge->setWordWrap(true);
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() * 1.6);
    big.setBold(true);
    m_title->setFont(big);
    QFont text = font();
    text.setPointSizeF(text.pointSizeF() * 1.3);
    m_challenge->setFont(text);
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("stageReadout"));
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(text.pointSizeF());
    m_readout->setFont(mono);
    m_readoutFont = mono;
    m_readout->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_readout->hide();
    for (QAction* action : transport) {
        auto* b = new QToolButton(this);
        b->setDefaultAction(action);
        b->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
        b->setIconSize(QSize(32, 32));
        b->setFont(text);
        b->setMinimumSize(80, 60);
        b->setFocusPolicy(Qt::NoFocus); // the keyboard stays with the stage: Space, →, R
        m_buttons << b;
    }
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(8, 8, 8, 8);
    m_grid->setSpacing(6);
    setVertical(true);
}

void StageBar::setCaption(const QString& title, const QString& challenge)
{
    m_title->setText(title);
    m_challenge->setText(challenge);
    m_challenge->setVisible(!challenge.isEmpty());
}

void StageBar::setReadout(const QString& text)
{
    m_readout->setText(text);
    m_readout->setVisible(!text.isEmpty());
    fitReadout();
}

void StageBar::fitReadout()
{
    // The readout's lines are never cut: its font shrinks (to 7 pt at
    // least) until the longest line fits the column's width, or in a row
    // the width its grid cell got (the label asks for none, so a long
    // readout never makes the window wider than the screen).
    QFont font = m_readoutFont;
    const int room = m_vertical ? width() - m_grid->contentsMargins().left() - m_grid->contentsMargins().right()
                                : m_readout->width();
    if (room > 0) {
        const QStringList lines = m_readout->text().split(QLatin1Char('\n'));
        auto widest = [&](const QFont& f) {
            const QFontMetrics fm(f);
            int w = 0;
            for (const QString& line : lines)
                w = std::max(w, fm.horizontalAdvance(line));
            return w;
        };
        while (font.pointSizeF() > 7.0 && widest(font) > room)
            font.setPointSizeF(font.pointSizeF() - 0.5);
    }
    if (font != m_readout->font())
        m_readout->setFont(font);
}

void StageBar::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    fitReadout();
    // In a row the readout's cell is known once the grid has laid out.
    QTimer::singleShot(0, this, &StageBar::fitReadout);
}

void StageBar::setSliders(QWidget* sliders)
{
    // In a scroll area: however many sliders a lesson has, the bar never
    // asks the window to grow (a long list scrolls instead).
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("stageSlidersScroll"));
    scroll->setWidget(sliders);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    // Light text on the bar's dark background, like the caption.
    scroll->setPalette(palette());
    scroll->viewport()->setAutoFillBackground(false);
    sliders->setPalette(palette());
    m_sliders = scroll;
    setVertical(m_vertical);
}

void StageBar::setSlidersShown(bool shown)
{
    if (m_sliders)
        m_sliders->setVisible(shown);
}

void StageBar::setVertical(bool vertical)
{
    m_vertical = vertical;
    while (m_grid->count() > 0)
        delete m_grid->takeAt(0); // the layout item only; the widget stays
    for (int k = 0; k < m_grid->rowCount(); ++k) // no stretch carries over from the other orientation
        m_grid->setRowStretch(k, 0);
    for (int k = 0; k < m_grid->columnCount(); ++k)
        m_grid->setColumnStretch(k, 0);
    if (vertical) {
        // Title, challenge, then the buttons two by two, at the top of the column.
        m_grid->addWidget(m_title, 0, 0, 1, 2);
        m_grid->addWidget(m_challenge, 1, 0, 1, 2);
        for (qsizetype i = 0; i < m_buttons.size(); ++i)
            m_grid->addWidget(m_buttons[i], 2 + static_cast<int>(i / 2), static_cast<int>(i % 2));
        const int after = 2 + static_cast<int>((m_buttons.size() + 1) / 2);
        m_grid->addWidget(m_readout, after, 0, 1, 2);
        if (m_sliders)
            m_grid->addWidget(m_sliders, after + 1, 0, 1, 2);
        m_grid->setRowStretch(after + 2, 1);
    } else {
        // One row: the caption, then the buttons.
        m_grid->addWidget(m_title, 0, 0);
        m_grid->addWidget(m_challenge, 1, 0);
        m_grid->addWidget(m_readout, 0, 1, 2, 1);
        for (qsizetype i = 0; i < m_buttons.size(); ++i)
            m_grid->addWidget(m_buttons[i], 0, 2 + static_cast<int>(i), 2, 1);
        if (m_sliders) // a row of its own under the caption and the buttons
            m_grid->addWidget(m_sliders, 2, 0, 1, 2 + static_cast<int>(m_buttons.size()));
        m_grid->setColumnStretch(0, 1);
        m_grid->setColumnStretch(1, 1); // the readout: as wide as the caption
    }
}

} // namespace forcelab
