#include "ui/docks/code_dock.h"

#include "ui/canvas/simulation_controller.h"

#include "lessons/lesson_controls.h"
#include "sim/world/parameters.h"
#include "ui/script/script_pieces.h"

#include <QButtonGroup>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace forcelab {

namespace {

qsizetype leadingSpaces(const QString& line)
{
    qsizetype n = 0;
    while (n < line.size() && line[n] == QLatin1Char(' '))
        ++n;
    return n;
}

} // namespace

CodeDock::CodeDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("Code"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("codeDock"));
    m_view = new QTextBrowser(this);
    m_view->setObjectName(QStringLiteral("codeView"));
    m_view->setAccessibleName(tr("The simulation code of this stage"));
    m_view->setLineWrapMode(QTextEdit::NoWrap);
    // The switch: the engine's C++ or the course's JavaScript.
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto* row = new QHBoxLayout;
    row->setContentsMargins(4, 2, 4, 0);
    auto* group = new QButtonGroup(body);
    auto addButton = [&](const QString& text, const QString& name, const QString& tip) {
        auto* button = new QToolButton(body);
        button->setText(text);
        button->setObjectName(name);
        button->setToolTip(tip);
        button->setCheckable(true);
        button->setAutoRaise(true);
        group->addButton(button);
        row->addWidget(button);
        return button;
    };
    m_cppButton = addButton(tr("C++"), QStringLiteral("codeCppButton"), tr("The engine's own code (sim/)"));
    m_jsButton = addButton(tr("JavaScript"), QStringLiteral("codeJsButton"),
                           tr("The code students write in the programming course (lessons/code/)"));
    m_cppButton->setChecked(true);
    row->addStretch(1);
    layout->addLayout(row);
    layout->addWidget(m_view, 1);
    setWidget(body);
    connect(m_cppButton, &QToolButton::toggled, this, [this](bool on) {
        if (on)
            setLanguage(Language::Cpp);
    });
    connect(m_jsButton, &QToolButton::toggled, this, [this](bool on) {
        if (on)
            setLanguage(Language::JavaScript);
    });
    connect(m_controller, &SimulationController::settingsChanged, this, &CodeDock::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &CodeDock::refresh);
    refresh();
}

void CodeDock::setLanguage(Language language)
{
    if (language == m_language)
        return;
    m_language = language;
    (language == Language::Cpp ? m_cppButton : m_jsButton)->setChecked(true);
    refresh();
}

QStringList CodeDock::shownPieces() const
{
    return m_pieces;
}

QString CodeDock::shownText() const
{
    return m_view->toPlainText();
}

void CodeDock::setLessonControls(const QStringList& controls)
{
    m_controlKeys.clear();
    for (const QString& control : controls)
        for (const QString& row : lessons::controlRows().value(control))
            if (const sim::Parameter* p = sim::findControl(row.toStdString()))
                m_controlKeys << QString::fromUtf8(p->key.data(), static_cast<qsizetype>(p->key.size()));
    refresh();
}

QStringList CodeDock::shownRegions() const
{
    QStringList names;
    for (const CodeRegion* r : m_shown)
        names << r->name;
    return names;
}

QStringList CodeDock::runningRegions() const
{
    QStringList names;
    for (const CodeRegion* r : m_shown)
        if (r->test.key.isEmpty() || r->test.holds(m_controller->world().settings()))
            names << r->name;
    return names;
}

QList<int> CodeDock::highlightedLines(const QString& region) const
{
    QList<int> lines;
    for (const CodeRegion* r : m_shown)
        if (r->name == region)
            for (const CodeLine& l : r->lines)
                if (!l.test.key.isEmpty() && l.test.holds(m_controller->world().settings()))
                    lines << l.number;
    return lines;
}

void CodeDock::refresh()
{
    const sim::WorldSettings& s = m_controller->world().settings();
    m_shown = regionsFor(s, m_controlKeys); // kept for both languages: the tests ask what C++ would show
    const QString html = m_language == Language::Cpp ? cppHtml(s) : javaScriptHtml(s);
    if (m_language == Language::Cpp)
        m_pieces.clear();
    // Readable from the back of a room at 1024×768: no smaller than 12 pt.
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(std::max(12.0, mono.pointSizeF()));
    m_view->document()->setDefaultFont(mono);
    m_view->setHtml(html);
}

QString CodeDock::cppHtml(const sim::WorldSettings& s)
{
    // Running code in dark text; code a switch would run in grey; a line
    // that a switch turns on, on a yellow band while it is on.
    QString html = QStringLiteral("<style>pre{margin:0 0 10px 0;} .off{color:#8a8f98;} .on{background:#fff2a8;} "
                                  ".n{color:#8a8f98;} h4{margin:6px 0 2px 0;}</style>");
    if (m_shown.isEmpty())
        html += tr("<p>This stage runs no marked code.</p>");
    for (const CodeRegion* r : m_shown) {
        const bool runs = r->test.key.isEmpty() || r->test.holds(s);
        html += QStringLiteral("<h4>%1 <span class='n'>— sim/%2%3</span></h4><pre%4>")
                    .arg(r->title.toHtmlEscaped(), r->file.toHtmlEscaped(),
                         runs ? QString() : tr(", runs when %1 = %2").arg(r->test.key, r->test.value),
                         runs ? QString() : QStringLiteral(" class='off'"));
        // The region's common indentation is left out, so it starts at the margin.
        qsizetype indent = std::numeric_limits<qsizetype>::max();
        for (const CodeLine& l : r->lines)
            if (!l.text.trimmed().isEmpty())
                indent = std::min(indent, leadingSpaces(l.text));
        for (const CodeLine& l : r->lines) {
            const bool on = !l.test.key.isEmpty() && l.test.holds(s);
            html += QStringLiteral("<span class='n'>%1</span>  %2%3%4\n")
                        .arg(l.number, 4)
                        .arg(on ? QStringLiteral("<span class='on'>") : QString(), l.text.mid(indent).toHtmlEscaped(),
                             on ? QStringLiteral("</span>") : QString());
        }
        html += QStringLiteral("</pre>");
    }
    return html;
}

QString CodeDock::javaScriptHtml(const sim::WorldSettings& s)
{
    // Every piece the settings run, whole, in the order the program loads them.
    const ScriptPieces pieces = scriptPiecesFor(s, m_controller->spawn());
    m_pieces = pieces.files;
    QString html = QStringLiteral("<style>pre{margin:0 0 10px 0;} .n{color:#8a8f98;} h4{margin:6px 0 2px 0;} "
                                  ".missing{color:#a33;}</style>");
    html += tr("<p>The code of this stage in JavaScript, as students write it. It runs beside the engine "
               "and moves the balls the same, to the last bit (test_script_reference).</p>");
    if (!pieces.missing.isEmpty())
        html += tr("<p class='missing'>Not written in JavaScript yet: %1.</p>")
                    .arg(pieces.missing.join(QStringLiteral(", ")).toHtmlEscaped());
    for (const QString& name : pieces.files) {
        html += QStringLiteral("<h4>%1 <span class='n'>— lessons/code/%1</span></h4><pre>").arg(name.toHtmlEscaped());
        html += scriptPieceSource(name).toHtmlEscaped();
        html += QStringLiteral("</pre>");
    }
    return html;
}

} // namespace forcelab
