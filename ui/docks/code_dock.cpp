#include "ui/docks/code_dock.h"

#include "ui/canvas/simulation_controller.h"

#include "lessons/lesson_controls.h"
#include "sim/world/parameters.h"

#include <QFontDatabase>
#include <QTextBrowser>

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
    setWidget(m_view);
    connect(m_controller, &SimulationController::settingsChanged, this, &CodeDock::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &CodeDock::refresh);
    refresh();
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
    m_shown = regionsFor(s, m_controlKeys);
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
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_view->document()->setDefaultFont(mono);
    m_view->setHtml(html);
}

} // namespace forcelab
