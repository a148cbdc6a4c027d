#include "ui/stage/stage_bar.h"

#include "ui/stage/arrow_legend_view.h"

#include <QAction>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QVBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QToolButton>

#include <algorithm>
#include <functional>
#include <limits>

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
    // A lesson's words are never rich text here: Qt would load what an <img>
    // names (lessons/lesson_markup.h keeps that to the lesson pane).
    m_title->setTextFormat(Qt::PlainText);
    m_challenge->setTextFormat(Qt::PlainText);
    m_challenge->setAlignment(Qt::AlignLeft | Qt::AlignTop); // if anything is cut, never the start
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("stageReadout"));
    m_readout->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    // Each label fits its text again whenever the grid gives it a new size.
    m_readout->installEventFilter(this);
    m_challenge->installEventFilter(this);
    m_readout->hide();
    m_legend = new ArrowLegendView(this);
    for (QAction* action : transport) {
        auto* b = new QToolButton(this);
        b->setDefaultAction(action);
        b->setToolButtonStyle(Qt::ToolButtonTextUnderIcon);
        b->setIconSize(QSize(32, 32));
        b->setMinimumSize(80, 60); // 72 px wide in a row (setVertical)
        b->setFocusPolicy(Qt::NoFocus); // the keyboard stays with the stage: Space, →, R
        // A button shows only while its action is visible (a tool button
        // outside a tool bar does not follow it by itself).
        b->setVisible(action->isVisible());
        connect(action, &QAction::changed, b, [b, action] { b->setVisible(action->isVisible()); });
        m_buttons << b;
    }
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(8, 8, 8, 8);
    m_grid->setSpacing(6);
    applyFonts();
    setVertical(true);
}

// The bar's text sizes, from the window's (the desktop's, the projector
// theme's, times the teacher's text size): the title 1.6 times it, the
// challenge, the readout and the buttons 1.3 times (the challenge larger,
// from the floor the stage sets).
void StageBar::applyFonts()
{
    QFont text = font();
    text.setPointSizeF(text.pointSizeF() * 1.3);
    // The challenge starts at the floor the stage sets from the screen's
    // height when that is larger; fitChallenge takes it down to fit.
    QFont challenge = text;
    challenge.setPointSizeF(std::max(text.pointSizeF(), pointsOfPixels(m_textFloor)));
    m_challengeFont = challenge;
    m_challenge->setFont(challenge);
    QFont big = font(); // the title never smaller than the challenge's start
    big.setPointSizeF(std::max(big.pointSizeF() * 1.6, challenge.pointSizeF()));
    big.setBold(true);
    m_title->setFont(big);
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    // The readout starts at the floor too: its numbers are read from the
    // back row as much as the challenge.
    mono.setPointSizeF(std::max(text.pointSizeF(), pointsOfPixels(m_textFloor)));
    m_readout->setFont(mono);
    m_readoutFont = mono;
    QFont legend = mono; // read as the readout is
    legend.setFamily(font().family());
    m_legend->setFont(legend);
    m_fitFont = mono;
    m_fitKey = {}; // the readout's size is searched for again
    for (QToolButton* b : m_buttons)
        b->setFont(text);
}

double StageBar::pointsOfPixels(double pixels) const
{
    return pixels * 72.0 / (logicalDpiY() > 0 ? logicalDpiY() : 96);
}

void StageBar::setTextFloor(double pixels)
{
    if (std::abs(pixels - m_textFloor) < 0.5)
        return;
    m_textFloor = pixels;
    applyFonts();
    scheduleFit();
}

void StageBar::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange && m_grid) {
        applyFonts();
        updateGeometry();
        scheduleFit();
        emit readoutRoomChanged(); // the readout's form may change with its size
    }
}

void StageBar::setCaption(const QString& title, const QString& challenge)
{
    m_title->setText(title);
    m_challengeText = challenge;
    m_challenge->setText(challenge);
    m_challenge->setToolTip(QString());
    m_challenge->setFont(m_challengeFont);
    m_challenge->setVisible(!challenge.isEmpty());
    scheduleFit(); // once the grid has laid the new text out
}

void StageBar::setReadout(const QString& text)
{
    const bool wasHidden = m_readout->isHidden();
    m_readoutText = text; // fitReadout sets the label's text
    m_readout->setVisible(!text.isEmpty());
    if (!m_vertical && m_readout->isHidden() != wasHidden)
        setVertical(false); // in a row the caption takes the readout's room when there is none
    fitReadout();
}

void StageBar::setArrowLegend(const QList<ArrowLegendRow>& rows)
{
    m_legend->setRows(rows);
    m_legend->setVisible(m_legend->hasRows());
    if (!m_vertical && legendUnderReadout(width(), m_buttonRows) != m_legendUnderReadout)
        setVertical(false);
}

namespace {

// The most text columns a row's readout is set in.
constexpr int kMostReadoutColumns = 3;

// `lines` set in `columns` text columns side by side (monospace: each line
// padded to its column's widest), read down the first column, then the
// next. A column starts only at a line that starts a group (not indented,
// so "  potential" stays under "energy: kinetic"), at the breaks that make
// the longest column shortest; empty when there are not enough groups.
QStringList flowLines(const QStringList& lines, int columns)
{
    if (columns <= 1)
        return lines;
    QList<int> starts; // where a column may start
    for (qsizetype i = 1; i < lines.size(); ++i)
        if (!lines[i].startsWith(QLatin1Char(' ')))
            starts << static_cast<int>(i);
    if (starts.size() < columns - 1)
        return {};
    // Every choice of columns − 1 breaks among the starts (a readout has a
    // dozen lines, so there are few).
    QList<int> best, pick;
    int bestLongest = std::numeric_limits<int>::max();
    const int n = static_cast<int>(lines.size());
    std::function<void(int)> choose = [&](int from) {
        if (pick.size() == columns - 1) {
            int longest = 0, begin = 0;
            for (int k = 0; k <= pick.size(); ++k) {
                const int end = k < pick.size() ? pick[k] : n;
                longest = std::max(longest, end - begin);
                begin = end;
            }
            if (longest < bestLongest) {
                bestLongest = longest;
                best = pick;
            }
            return;
        }
        for (qsizetype i = from; i < starts.size(); ++i) {
            pick << starts[i];
            choose(static_cast<int>(i) + 1);
            pick.removeLast();
        }
    };
    choose(0);
    QList<QStringList> parts;
    int begin = 0;
    for (int k = 0; k <= best.size(); ++k) {
        const int end = k < best.size() ? best[k] : n;
        parts << lines.mid(begin, end - begin);
        begin = end;
    }
    QStringList out(bestLongest);
    for (qsizetype k = 0; k < parts.size(); ++k) {
        qsizetype width = 0;
        for (const QString& line : parts[k])
            width = std::max(width, line.size());
        for (int row = 0; row < bestLongest; ++row) {
            const QString cell = row < parts[k].size() ? parts[k][row] : QString();
            out[row] += k + 1 < parts.size() ? cell.leftJustified(width + 3) : cell;
        }
    }
    for (QString& line : out)
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
    return out;
}

// The size `lines` take in `font`: the widest line, and all lines stacked.
QSize textSize(const QFont& font, const QStringList& lines)
{
    const QFontMetrics fm(font);
    int w = 0;
    for (const QString& line : lines)
        w = std::max(w, fm.horizontalAdvance(line));
    return QSize(w, static_cast<int>(lines.size()) * fm.lineSpacing());
}

// Whether `lines` in `font` fit `room`, both ways.
bool fitsIn(const QFont& font, const QStringList& lines, QSize room)
{
    const QSize need = textSize(font, lines);
    return need.width() <= room.width() && need.height() <= room.height();
}

// The height `text` takes in `font`, wrapped at word breaks to `width`.
int wrappedHeight(const QFont& font, int width, const QString& text)
{
    return QFontMetrics(font).boundingRect(QRect(0, 0, width, 1 << 20), Qt::TextWordWrap, text).height();
}

// The text columns (1 to `mostColumns`) and font that set `lines` at the
// largest size that fits `room`: the readout's own font, shrunk in steps of
// half a point to 7 pt at least (then it may not fit).
struct ReadoutFit {
    QFont font;
    QStringList lines;
    int columns = 1;
};
ReadoutFit bestFit(const QFont& own, const QStringList& lines, QSize room, int mostColumns)
{
    // A setting that fits beats one that does not; then the larger font
    // wins, and of equal ones the fewer columns.
    ReadoutFit best{own, lines};
    bool bestFits = false;
    for (int columns = 1; columns <= mostColumns; ++columns) {
        const QStringList flowed = flowLines(lines, columns);
        if (flowed.isEmpty())
            continue;
        QFont f = own;
        while (f.pointSizeF() - 0.5 >= 7.0 && !fitsIn(f, flowed, room))
            f.setPointSizeF(f.pointSizeF() - 0.5);
        const bool ok = fitsIn(f, flowed, room);
        if (columns == 1 || (ok && (!bestFits || f.pointSizeF() > best.font.pointSizeF()))) {
            best = {f, flowed, columns};
            bestFits = ok;
        }
    }
    return best;
}

// The readout's text with every digit as 0: in the readout's fixed-width
// font two texts of the same shape take the same room, whatever the
// numbers.
QString shapeOf(QString text)
{
    for (QChar& c : text)
        if (c.isDigit())
            c = QLatin1Char('0');
    return text;
}

} // namespace

bool StageBar::readoutFits(const QString& text) const
{
    if (m_readoutRoom.isEmpty())
        return true;
    QFont readable = m_readoutFont;
    readable.setPointSizeF(m_readoutFont.pointSizeF() * 0.75);
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int columns = 1; columns <= (m_vertical ? 1 : kMostReadoutColumns); ++columns) {
        const QStringList flowed = flowLines(lines, columns);
        if (!flowed.isEmpty() && fitsIn(readable, flowed, m_readoutRoom))
            return true;
    }
    return false;
}

double StageBar::readoutPointSize(const QString& text) const
{
    if (m_readoutRoom.isEmpty())
        return m_readoutFont.pointSizeF();
    return bestFit(m_readoutFont, text.split(QLatin1Char('\n')), m_readoutRoom,
                   m_vertical ? 1 : kMostReadoutColumns)
        .font.pointSizeF();
}

// The width of a row bar's widest row of shown buttons, spacing included,
// and of the arrow legend under them when it goes there.
int StageBar::rowButtonsWidth(int rows, bool withLegend) const
{
    QList<const QToolButton*> shown;
    for (const QToolButton* b : m_buttons)
        if (!b->isHidden())
            shown << b;
    const qsizetype perRow = (shown.size() + rows - 1) / std::max(1, rows);
    int widest = 0;
    for (qsizetype start = 0; start < shown.size(); start += std::max<qsizetype>(1, perRow)) {
        int w = 0;
        for (qsizetype i = start; i < std::min(shown.size(), start + perRow); ++i)
            w += std::max(shown[i]->minimumWidth(), shown[i]->sizeHint().width()) + m_grid->horizontalSpacing();
        widest = std::max(widest, w);
    }
    if (withLegend && !m_legend->isHidden())
        widest = std::max(widest, m_legend->sizeHint().width() + m_grid->horizontalSpacing());
    return widest;
}

// The height of a row bar's buttons in `rows` rows, without the legend.
int StageBar::rowButtonsHeight(int rows) const
{
    int buttonHeight = 0;
    for (const QToolButton* b : m_buttons)
        if (!b->isHidden())
            buttonHeight = std::max({buttonHeight, b->minimumHeight(), b->sizeHint().height()});
    return rows * buttonHeight + (rows - 1) * m_grid->verticalSpacing();
}

// The readout at its starting size in the text columns that make it
// lowest within 60% of `free` (sizeReadoutColumn's most); empty when the
// bar shows none.
QSize StageBar::rowReadoutAtFloor(int free) const
{
    if (m_readout->isHidden() || m_readoutText.isEmpty())
        return {};
    const QStringList lines = m_readoutText.split(QLatin1Char('\n'));
    QSize best = textSize(m_readoutFont, lines);
    for (int columns = 2; columns <= kMostReadoutColumns; ++columns) {
        const QStringList flowed = flowLines(lines, columns);
        if (flowed.isEmpty())
            continue;
        const QSize s = textSize(m_readoutFont, flowed);
        if (best.width() > free * 6 / 10 || (s.width() <= free * 6 / 10 && s.height() < best.height()))
            best = s;
    }
    return best;
}

// In a row the arrow legend goes under the readout when the two together
// are no taller than the buttons and the legend fits the readout's widest
// column; else under the buttons (which may make the bar taller).
bool StageBar::legendUnderReadout(int width, int rows) const
{
    if (m_legend->isHidden() || m_readout->isHidden() || m_readoutText.isEmpty())
        return false;
    const QMargins margins = m_grid->contentsMargins();
    const int free = width - margins.left() - margins.right() - rowButtonsWidth(rows, false) - m_grid->horizontalSpacing();
    const QSize legend = m_legend->sizeHint();
    return rowReadoutAtFloor(free).height() + m_grid->verticalSpacing() + legend.height() <= rowButtonsHeight(rows) &&
           legend.width() <= free * 6 / 10;
}

int StageBar::rowHeightAtFloor(int width, int rows) const
{
    const QMargins margins = m_grid->contentsMargins();
    const int hs = m_grid->horizontalSpacing();
    const int vs = m_grid->verticalSpacing();
    const bool under = legendUnderReadout(width, rows);
    const QSize legend = m_legend->isHidden() ? QSize() : m_legend->sizeHint();
    int buttons = rowButtonsHeight(rows);
    if (!m_legend->isHidden() && !under)
        buttons += vs + legend.height();
    int free = width - margins.left() - margins.right() - rowButtonsWidth(rows, !under) - hs;
    const QSize shown = rowReadoutAtFloor(free);
    int readout = shown.height();
    if (!shown.isEmpty()) {
        int readoutWidth = std::min(shown.width(), free * 6 / 10);
        if (under) {
            readout += vs + legend.height();
            readoutWidth = std::max(readoutWidth, legend.width());
        }
        free -= readoutWidth + hs;
    }
    if (free <= 0)
        return QWIDGETSIZE_MAX;
    int caption = m_title->heightForWidth(free);
    if (!m_challengeText.isEmpty())
        caption += vs + wrappedHeight(m_challengeFont, free, m_challengeText);
    return std::max({caption, readout, buttons}) + margins.top() + margins.bottom();
}

int StageBar::columnWidthAtFloor(const QString& readout) const
{
    const QMargins margins = m_grid->contentsMargins();
    int buttons = m_grid->horizontalSpacing();
    for (qsizetype i = 0; i < std::min<qsizetype>(2, m_buttons.size()); ++i)
        buttons += std::max(m_buttons[i]->minimumWidth(), m_buttons[i]->sizeHint().width());
    const int lines = readout.isEmpty() ? 0 : textSize(m_readoutFont, readout.split(QLatin1Char('\n'))).width() + 2;
    const int legend = m_legend->isHidden() ? 0 : m_legend->sizeHint().width();
    return std::max({buttons, lines, legend}) + margins.left() + margins.right();
}

void StageBar::setButtonRows(int rows)
{
    rows = std::clamp(rows, 1, 2);
    if (rows == m_buttonRows)
        return;
    m_buttonRows = rows;
    if (!m_vertical)
        setVertical(false);
}

void StageBar::fitReadout()
{
    // The readout's lines are never cut: its font shrinks (to 7 pt at
    // least) until they fit the column's width, or in a row the cell its
    // grid gave it (the label asks for no width, so a long readout never
    // makes the window wider than the screen), and in a row its height. A
    // row is short and wide, so there the lines may also be set in two or
    // three text columns, whichever gives the largest font.
    //
    // The readout changes every frame but its shape seldom does, so the
    // search for the size and the columns runs only when the shape, the
    // room, the bar or what shares the row with the readout changed; in
    // between, the new numbers go into the columns and size found last.
    const QStringList lines = m_readoutText.split(QLatin1Char('\n'));
    const QMargins margins = m_grid->contentsMargins();
    const int labelWidth = m_readout->contentsRect().width();
    const QSize room = m_vertical ? QSize(labelWidth > 0 ? labelWidth : width() - margins.left() - margins.right(),
                                          QWIDGETSIZE_MAX)
                                  : m_readout->contentsRect().size();
    int shownButtons = 0;
    for (const QToolButton* b : m_buttons)
        shownButtons += b->isHidden() ? 0 : 1;
    const FitKey key{shapeOf(m_readoutText), room,           size(),        m_challengeText, m_vertical,
                     m_readout->isHidden(),   shownButtons, m_buttonRows};
    if (!(key == m_fitKey)) {
        m_fitKey = key;
        if (!m_vertical && !m_readout->isHidden())
            sizeReadoutColumn(lines);
        m_fitFont = m_readoutFont;
        m_fitColumns = 1;
        if (room.width() > 0 && room.height() > 0 && !m_readout->isHidden()) {
            const ReadoutFit fit = bestFit(m_readoutFont, lines, room, m_vertical ? 1 : kMostReadoutColumns);
            m_fitFont = fit.font;
            m_fitColumns = fit.columns;
            if (room != m_readoutRoom) {
                m_readoutRoom = room;
                emit readoutRoomChanged();
            }
        }
    }
    const QFont& font = m_fitFont;
    const QStringList flowed = flowLines(lines, m_fitColumns);
    const QString text = (flowed.isEmpty() ? lines : flowed).join(QLatin1Char('\n'));
    if (text != m_readout->text())
        m_readout->setText(text);
    if (font != m_readout->font())
        m_readout->setFont(font);
}

// In a row the readout's column is as wide as its lines need at the size
// (and in the text columns) that suit them best in a column 60% of the
// width the buttons leave and the row's height, but no narrower than 30%
// of that width; the caption has the rest. (A change of less than 12 px is
// left alone, so the caption does not reflow as the numbers tick.)
void StageBar::sizeReadoutColumn(const QStringList& lines)
{
    const QMargins margins = m_grid->contentsMargins();
    const int spacing = m_grid->horizontalSpacing();
    const int free =
        width() - margins.left() - margins.right() - rowButtonsWidth(m_buttonRows, !m_legendUnderReadout) - spacing;
    if (free <= 0)
        return;
    const int tall = m_readout->contentsRect().height() > 0 ? m_readout->contentsRect().height()
                                                             : height() - margins.top() - margins.bottom();
    const ReadoutFit fit = bestFit(m_readoutFont, lines, QSize(free * 6 / 10, tall), kMostReadoutColumns);
    int want = std::clamp(textSize(fit.font, fit.lines).width() + 1, free * 3 / 10, free * 6 / 10);
    // The challenge comes first: while it would not fit beside the readout
    // at the bar's own text size, the readout gives back width, down to
    // what its lines need at 8 pt.
    if (!m_challengeText.isEmpty()) {
        QFont small = m_readoutFont;
        small.setPointSizeF(std::min(8.0, m_readoutFont.pointSizeF()));
        const ReadoutFit tight = bestFit(small, lines, QSize(free * 6 / 10, tall), kMostReadoutColumns);
        const int least = textSize(tight.font, tight.lines).width() + 1;
        QFont plain = m_challengeFont;
        plain.setPointSizeF(font().pointSizeF());
        auto challengeFits = [&](int readout) {
            const int caption = free - readout;
            const int room = tall - m_title->heightForWidth(caption) - m_grid->verticalSpacing();
            return wrappedHeight(plain, caption, m_challengeText) <= room;
        };
        while (want - 8 >= least && !challengeFits(want))
            want -= 8;
    }
    if (m_legendUnderReadout) // the legend shares the readout's column
        want = std::max(want, m_legend->sizeHint().width());
    if (std::abs(want - m_readoutColumn) <= 12)
        return;
    m_readoutColumn = want;
    m_grid->setColumnMinimumWidth(1, want);
}

// The challenge is never cut off: in a row, in the room the grid gives it,
// its font shrinks (to the window's own text size at least) until every line
// fits; if it still does not, it ends after the last whole word that fits,
// with "…", and the whole challenge is its tooltip (and in the Lesson panel).
void StageBar::fitChallenge()
{
    if (m_challengeText.isEmpty())
        return;
    if (m_vertical) {
        // A column gives the challenge the height its lines need: from the
        // floor's size down (never below the bar's 1.3 times the window's
        // text) until the whole column, sliders too, fits the bar's height.
        m_challenge->setText(m_challengeText);
        m_challenge->setToolTip(QString());
        QFont f = m_challengeFont;
        const double least = font().pointSizeF() * 1.3;
        // The sliders count with two rows at most: the rest of them scroll,
        // and the challenge keeps its size.
        const int sliders = m_sliders && !m_sliders->isHidden() ? m_sliders->sizeHint().height() : 0;
        const int slidersKept = std::min(sliders, 2 * (QFontMetrics(font()).lineSpacing() * 3));
        auto fits = [&] {
            if (f != m_challenge->font())
                m_challenge->setFont(f);
            return m_grid->totalHeightForWidth(width()) - sliders + slidersKept <= height();
        };
        while (f.pointSizeF() - 0.5 >= least && !fits())
            f.setPointSizeF(f.pointSizeF() - 0.5);
        fits();
        return;
    }
    const QRect room = m_challenge->contentsRect();
    if (room.width() <= 0 || room.height() <= 0)
        return;
    auto height = [&](const QFont& f, const QString& s) { return wrappedHeight(f, room.width(), s); };
    QFont f = m_challengeFont;
    const qreal smallest = font().pointSizeF();
    while (f.pointSizeF() - 0.5 >= smallest && height(f, m_challengeText) > room.height())
        f.setPointSizeF(f.pointSizeF() - 0.5);
    if (height(f, m_challengeText) > room.height())
        f.setPointSizeF(smallest);
    QString shown = m_challengeText;
    if (height(f, shown) > room.height()) {
        QStringList words = m_challengeText.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        while (words.size() > 1 && height(f, words.join(QLatin1Char(' ')) + QStringLiteral(" …")) > room.height())
            words.removeLast();
        shown = words.join(QLatin1Char(' ')) + QStringLiteral(" …");
    }
    if (f != m_challenge->font())
        m_challenge->setFont(f);
    if (shown != m_challenge->text())
        m_challenge->setText(shown);
    m_challenge->setToolTip(shown == m_challengeText ? QString() : m_challengeText);
}

bool StageBar::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Resize) {
        if (watched == m_readout || watched == m_challenge)
            scheduleFit();
    }
    return QWidget::eventFilter(watched, event);
}

void StageBar::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (!m_vertical && legendUnderReadout(width(), m_buttonRows) != m_legendUnderReadout)
        setVertical(false);
    fitReadout();
    // In a row the readout's and the challenge's cells are known once the
    // grid has laid out.
    scheduleFit();
}

// Every request for a fit made before the queued call runs is served by
// that one call: the grid's layout requests and the labels' resizes come in
// bursts, and each fit needs the room they settle on, not the rooms between.
void StageBar::scheduleFit()
{
    if (m_fitQueued)
        return;
    m_fitQueued = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_fitQueued = false;
            fitReadout();
            fitChallenge();
        },
        Qt::QueuedConnection);
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

void StageBar::unfitChallenge()
{
    m_challenge->setFont(m_challengeFont);
    m_challenge->setText(m_challengeText);
    scheduleFit();
}

void StageBar::setSlidersShown(bool shown)
{
    if (m_sliders) {
        m_sliders->setVisible(shown);
        // In a row the sliders take the height of their rows and no more:
        // the caption above them has the rest.
        const auto* scroll = qobject_cast<const QScrollArea*>(m_sliders);
        const int rows = scroll && scroll->widget() ? scroll->widget()->sizeHint().height() : QWIDGETSIZE_MAX;
        m_sliders->setMaximumHeight(m_vertical ? QWIDGETSIZE_MAX : rows);
    }
    if (m_vertical)
        stretchColumnRows();
}

// In a column the sliders' area takes the height left under the readout,
// so they scroll only when they do not fit the screen; without sliders an
// empty row takes it and the rest stays at the top.
void StageBar::stretchColumnRows()
{
    const int after = 2 + static_cast<int>((m_buttons.size() + 1) / 2);
    const bool sliders = m_sliders && !m_sliders->isHidden();
    m_grid->setRowStretch(after + 2, sliders ? 1 : 0);
    m_grid->setRowStretch(after + 3, sliders ? 0 : 1);
}

void StageBar::setVertical(bool vertical)
{
    m_vertical = vertical;
    while (m_grid->count() > 0)
        delete m_grid->takeAt(0); // the layout item only; the widget stays
    for (int k = 0; k < m_grid->rowCount(); ++k) // no stretch carries over from the other orientation
        m_grid->setRowStretch(k, 0);
    for (int k = 0; k < m_grid->columnCount(); ++k) {
        m_grid->setColumnStretch(k, 0);
        m_grid->setColumnMinimumWidth(k, 0);
    }
    m_readoutColumn = 0;
    m_fitKey = {}; // the readout's column and size are found again in the new grid
    // A row has six buttons across when the lesson's sliders wait for the
    // Sliders button: a little narrower there, so the caption keeps room.
    // In a column the buttons share its width (a layout of fixed-size
    // buttons would sit centred, narrower than the column, and squeeze the
    // readout and the challenge that span it).
    for (QToolButton* b : m_buttons) {
        b->setMinimumWidth(vertical ? 80 : 72);
        b->setSizePolicy(vertical ? QSizePolicy::Preferred : QSizePolicy::Fixed, QSizePolicy::Fixed);
    }
    m_legendUnderReadout = false;
    if (vertical) {
        // Title, challenge, then the buttons two by two, at the top of the column.
        m_grid->addWidget(m_title, 0, 0, 1, 2);
        m_grid->addWidget(m_challenge, 1, 0, 1, 2);
        for (qsizetype i = 0; i < m_buttons.size(); ++i)
            m_grid->addWidget(m_buttons[i], 2 + static_cast<int>(i / 2), static_cast<int>(i % 2));
        const int after = 2 + static_cast<int>((m_buttons.size() + 1) / 2);
        m_grid->addWidget(m_readout, after, 0, 1, 2);
        m_grid->addWidget(m_legend, after + 1, 0, 1, 2, Qt::AlignLeft);
        if (m_sliders)
            m_grid->addWidget(m_sliders, after + 2, 0, 1, 2);
        // The column's width goes to its two columns, not to gaps between
        // the fixed-size buttons: the readout and the challenge span both.
        m_grid->setColumnStretch(0, 1);
        m_grid->setColumnStretch(1, 1);
        stretchColumnRows();
    } else {
        // One row: the caption, then the buttons. Without a readout the
        // caption has the readout's room too.
        const int captionColumns = m_readout->isHidden() ? 2 : 1;
        m_grid->addWidget(m_title, 0, 0, 1, captionColumns);
        m_grid->addWidget(m_challenge, 1, 0, 1, captionColumns);
        m_legendUnderReadout = legendUnderReadout(width(), m_buttonRows);
        if (m_legendUnderReadout) {
            auto* column = new QVBoxLayout;
            column->setSpacing(m_grid->verticalSpacing());
            column->addWidget(m_readout, 1);
            column->addWidget(m_legend, 0, Qt::AlignLeft);
            m_grid->addLayout(column, 0, 1, 2, 1);
        } else if (!m_readout->isHidden()) {
            m_grid->addWidget(m_readout, 0, 1, 2, 1);
        }
        // The buttons in one row, or in two when the caption needs their width.
        auto* buttons = new QGridLayout;
        buttons->setSpacing(m_grid->horizontalSpacing());
        const int perRow = static_cast<int>((m_buttons.size() + m_buttonRows - 1) / m_buttonRows);
        for (qsizetype i = 0; i < m_buttons.size(); ++i)
            buttons->addWidget(m_buttons[i], static_cast<int>(i) / perRow, static_cast<int>(i) % perRow);
        if (!m_legendUnderReadout)
            buttons->addWidget(m_legend, m_buttonRows, 0, 1, perRow, Qt::AlignLeft);
        m_grid->addLayout(buttons, 0, 2, 2, 1, Qt::AlignTop);
        if (m_sliders) // a row of its own under the caption and the buttons
            m_grid->addWidget(m_sliders, 2, 0, 1, 3);
        m_grid->setColumnStretch(0, 1); // the readout's column: see sizeReadoutColumn
        // The challenge has all the height the title leaves, whatever its
        // text asks (fitChallenge fits the text to that room).
        m_grid->setRowStretch(1, 1);
    }
    scheduleFit();
}

} // namespace forcelab
