#include "ui/docks/step_apart_dock.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/script/script_world.h"

#include "sim/world/world.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QJSValue>
#include <QLabel>
#include <QMap>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <cmath>
#include <cstring>

namespace forcelab {

namespace {

// Wraps the script's own functions so that one step leaves a log of what each
// did to ball `apartBall`. Function declarations are properties of the global
// object and step(), move(), collide() look them up when they call them, so
// reassigning the global is what they then call; the lists (forces, afterMove)
// are read entry by entry, so their entries are replaced in place.
const char* const kPrelude = R"JS(
var apartLog = [];
var apartSub = -1;
var apartEval = 0;
function apartSnap(b) { return { x: b.x, y: b.y, vx: b.vx, vy: b.vy }; }
(function () {
  for (let k = 0; k < forces.length; k++) {
    const force = forces[k];
    forces[k] = function (world, state, acc, t) {
      const i = apartBall;
      const ax = acc[i].x, ay = acc[i].y;
      force(world, state, acc, t);
      apartLog.push({ kind: "force", name: force.name, sub: apartSub, evaluation: apartEval,
                      own: { x: acc[i].x - ax, y: acc[i].y - ay }, acc: { x: acc[i].x, y: acc[i].y } });
    };
  }
  if (typeof accelerations === "function") {
    const accelerations0 = accelerations;
    accelerations = function (world, state, t) {
      apartEval = apartEval + 1;
      const acc = accelerations0(world, state, t);
      apartLog.push({ kind: "acceleration", sub: apartSub, evaluation: apartEval,
                      trial: state !== apartBalls, acc: { x: acc[apartBall].x, y: acc[apartBall].y } });
      return acc;
    };
  }
  const move0 = move;
  move = function (world, balls, h, t) {
    apartSub = apartSub + 1;
    apartEval = 0;
    apartLog.push({ kind: "substep", sub: apartSub, h: h, t: t, before: apartSnap(balls[apartBall]) });
    move0(world, balls, h, t);
    apartLog.push({ kind: "move", sub: apartSub, after: apartSnap(balls[apartBall]) });
  };
  for (let k = 0; k < afterMove.length; k++) {
    const rule = afterMove[k];
    afterMove[k] = function (world, balls, h) {
      const entry = { kind: "rule", name: rule.name, sub: apartSub, before: apartSnap(balls[apartBall]) };
      apartLog.push(entry);
      rule(world, balls, h);
      apartLog.push({ kind: "ruleEnd", name: rule.name, sub: apartSub, after: apartSnap(balls[apartBall]) });
    };
  }
  if (typeof findContacts === "function") {
    const find0 = findContacts;
    findContacts = function (balls) {
      const contacts = find0(balls);
      apartLog.push({ kind: "detect", sub: apartSub, count: contacts.length,
                      pairs: contacts.filter((p) => p[0] === apartBall || p[1] === apartBall).map((p) => [p[0], p[1]]),
                      after: apartSnap(balls[apartBall]) });
      return contacts;
    };
  }
  if (typeof respond === "function") {
    const respond0 = respond;
    respond = function (e, d, n, wa, wb, a, b) {
      const me = apartBalls[apartBall];
      const before = apartSnap(me);
      respond0(e, d, n, wa, wb, a, b);
      if (a === me || b === me) {
        apartLog.push({ kind: "respond", sub: apartSub, other: apartBalls.indexOf(a === me ? b : a),
                        before: before, after: apartSnap(me) });
      }
    };
  }
  if (typeof pushApart === "function") {
    const push0 = pushApart;
    pushApart = function (world, a, b, n, wa, wb, depth) {
      const me = apartBalls[apartBall];
      const before = apartSnap(me);
      push0(world, a, b, n, wa, wb, depth);
      if (a === me || b === me) {
        apartLog.push({ kind: "push", sub: apartSub, other: apartBalls.indexOf(a === me ? b : a), depth: depth,
                        before: before, after: apartSnap(me) });
      }
    };
  }
})();
)JS";

// A function of the loaded pieces: where it is and its lines.
struct FunctionText {
    QString file;
    int firstLine = 0; // 1-based
    QStringList lines;
};

// The text of `function NAME(` in the pieces, the last piece that defines it
// winning (as it does when they load), up to its closing brace at column 0.
FunctionText findFunction(const QStringList& pieces, const QString& name)
{
    FunctionText found;
    const QString head = QStringLiteral("function %1(").arg(name);
    for (const QString& piece : pieces) {
        const QStringList lines = scriptPieceSource(piece).split(QLatin1Char('\n'));
        for (int i = 0; i < lines.size(); ++i) {
            if (!lines[i].startsWith(head))
                continue;
            FunctionText f{piece, i + 1, {}};
            for (int j = i; j < lines.size(); ++j) {
                f.lines << lines[j];
                if (j > i && lines[j].startsWith(QLatin1Char('}')))
                    break;
            }
            found = f;
        }
    }
    return found;
}

// The lines of `f` that match `pattern` ("file:line  text"); the function's
// first line when none do, so a row always says where its code is.
QStringList codeLines(const FunctionText& f, const QString& pattern)
{
    QStringList out;
    if (f.file.isEmpty())
        return out;
    const QRegularExpression re(pattern);
    for (int i = 0; i < f.lines.size(); ++i)
        if (re.match(f.lines[i]).hasMatch())
            out << QStringLiteral("%1:%2  %3").arg(f.file).arg(f.firstLine + i).arg(f.lines[i].trimmed());
    if (out.isEmpty())
        out << QStringLiteral("%1:%2  %3").arg(f.file).arg(f.firstLine).arg(f.lines.value(0).trimmed());
    return out;
}

// The first line of `f` that matches `pattern`, or -1.
int firstMatch(const FunctionText& f, const QString& pattern)
{
    const QRegularExpression re(pattern);
    for (int i = 0; i < f.lines.size(); ++i)
        if (re.match(f.lines[i]).hasMatch())
            return i;
    return -1;
}

void setBall(StepApartRow& row, const QJSValue& snap)
{
    row.x = snap.property(QStringLiteral("x")).toNumber();
    row.y = snap.property(QStringLiteral("y")).toNumber();
    row.vx = snap.property(QStringLiteral("vx")).toNumber();
    row.vy = snap.property(QStringLiteral("vy")).toNumber();
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

QString full(double v) { return QString::number(v, 'g', 17); }

QString ruleWords(const QString& name)
{
    if (name == QLatin1String("bounceOnWalls"))
        return QObject::tr("Walls: is the ball outside the box?");
    if (name.contains(QLatin1String("peed")))
        return QObject::tr("Speed limit");
    return QObject::tr("Rule %1").arg(name);
}

} // namespace

StepApartDock::StepApartDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("One Step Apart"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("stepApartDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    m_title = new QLabel(body);
    m_title->setObjectName(QStringLiteral("stepApartTitle"));
    m_title->setWordWrap(true);
    layout->addWidget(m_title);
    auto* subStepRow = new QHBoxLayout;
    m_subStep = new QSpinBox(body);
    m_subStep->setObjectName(QStringLiteral("stepApartSubStep"));
    m_subStep->setRange(0, 1);
    m_subStep->setEnabled(false);
    m_subStep->setSpecialValueText(tr("all"));
    m_subStep->setAccessibleName(tr("Sub-step shown"));
    subStepRow->addWidget(new QLabel(tr("Sub-step shown:"), body));
    subStepRow->addWidget(m_subStep);
    subStepRow->addStretch(1);
    layout->addLayout(subStepRow);
    connect(m_subStep, &QSpinBox::valueChanged, this, [this] { render(); });
    m_view = new QTextBrowser(body);
    m_view->setObjectName(QStringLiteral("stepApartView"));
    QFont font = m_view->font();
    font.setPointSizeF(std::max(11.0, font.pointSizeF()));
    m_view->setFont(font);
    layout->addWidget(m_view, 1);
    auto* buttons = new QHBoxLayout;
    m_backButton = new QPushButton(tr("◀ Step back"), body);
    m_backButton->setObjectName(QStringLiteral("stepApartBack"));
    m_stepButton = new QPushButton(tr("Step ▶"), body);
    m_stepButton->setObjectName(QStringLiteral("stepApartStep"));
    buttons->addWidget(m_backButton);
    buttons->addWidget(m_stepButton);
    layout->addLayout(buttons);
    setWidget(body);

    connect(m_stepButton, &QPushButton::clicked, m_controller, &SimulationController::stepOnce);
    connect(m_backButton, &QPushButton::clicked, m_controller, [this] { m_controller->stepBack(); });
    for (auto signal : {&SimulationController::stepped, &SimulationController::seeked,
                        &SimulationController::sceneChanged, &SimulationController::settingsChanged})
        connect(m_controller, signal, this, &StepApartDock::refresh);
    connect(m_controller, &SimulationController::playingChanged, this, &StepApartDock::refresh);
}

int StepApartDock::shownSubStep() const { return m_subStep->value(); }

void StepApartDock::showSubStep(int subStep) { m_subStep->setValue(subStep); }

void StepApartDock::setSelectedBall(int ball)
{
    m_ball = std::max(0, ball);
    refresh();
}

void StepApartDock::showEvent(QShowEvent* event)
{
    QDockWidget::showEvent(event);
    if (m_stale)
        refresh();
}

void StepApartDock::refresh()
{
    // Hidden, it costs nothing: the step is taken apart when it is shown.
    if (!isVisible()) {
        m_stale = true;
        return;
    }
    m_stale = false;
    // While playing, every frame would only set the same note again.
    if (m_controller->isPlaying() && m_rows.isEmpty() && m_message == pauseNote())
        return;
    takeApart();
    // A few sub-steps are shown one after the other; with many, one at a
    // time (the first at first), so the list stays short enough to read.
    const int subSteps = std::max(1, m_controller->world().settings().time.substeps);
    if (subSteps != m_subSteps) {
        m_subSteps = subSteps;
        const QSignalBlocker block(m_subStep);
        m_subStep->setRange(0, subSteps);
        m_subStep->setValue(subSteps <= 4 ? 0 : 1);
    }
    m_subStep->setEnabled(subSteps > 1);
    render();
}

QString StepApartDock::pauseNote() const
{
    return tr("Pause to take a step apart: it is worked out for one step at a time, not for every frame.");
}

void StepApartDock::takeApart()
{
    m_rows.clear();
    m_message.clear();
    const sim::World& world = m_controller->world();
    // A JavaScript engine per frame at 60 Hz would slow the run it describes.
    if (m_controller->isPlaying()) {
        m_message = pauseNote();
        return;
    }
    if (world.balls().empty()) {
        m_message = tr("There is no ball to follow.");
        return;
    }
    const int ball = std::min(m_ball, world.balls().size() - 1);
    QStringList pieces;
    if (auto error = ScriptWorld::piecesFor(world, pieces)) {
        m_message = error->message;
        return;
    }
    ScriptWorld script;
    if (auto error = script.loadFrom(world)) {
        m_message = error->text();
        return;
    }
    script.engine().globalObject().setProperty(QStringLiteral("apartBall"), ball);
    script.engine().globalObject().setProperty(QStringLiteral("apartBalls"), script.ballsObject());
    if (auto error = script.evaluate(QString::fromUtf8(kPrelude), QStringLiteral("step_apart.js"))) {
        m_message = error->text();
        return;
    }
    if (auto error = script.step()) {
        m_message = error->text();
        return;
    }

    const FunctionText move = findFunction(pieces, QStringLiteral("move"));
    const FunctionText accelerations = findFunction(pieces, QStringLiteral("accelerations"));
    const int velocityLine = firstMatch(move, QStringLiteral(R"(b\.v[xy]\s*=[^=])"));
    const int positionLine = firstMatch(move, QStringLiteral(R"(b\.[xy]\s*=[^=])"));
    const int subSteps = world.settings().time.substeps;

    const QJSValue log = script.global(QStringLiteral("apartLog"));
    const int n = log.property(QStringLiteral("length")).toInt();
    StepApartRow last;
    QJSValue moveStart;
    int evaluations = 0;
    for (int k = 0; k < n; ++k) {
        const QJSValue e = log.property(static_cast<quint32>(k));
        const QString kind = e.property(QStringLiteral("kind")).toString();
        StepApartRow row = last;
        row.subStep = e.property(QStringLiteral("sub")).toInt();
        row.code.clear();
        row.note.clear();
        row.pairs.clear();
        row.other = -1;
        row.hasAcceleration = false;
        if (kind == QLatin1String("substep")) {
            setBall(row, e.property(QStringLiteral("before")));
            moveStart = e.property(QStringLiteral("before"));
            evaluations = 0;
            row.kind = StepApartRow::Kind::SubStep;
            row.stage = subSteps > 1 ? tr("Sub-step %1 of %2: h = %3 s, starting at").arg(row.subStep + 1).arg(subSteps)
                                           .arg(full(e.property(QStringLiteral("h")).toNumber()))
                                     : tr("The step starts: h = %1 s").arg(full(e.property(QStringLiteral("h")).toNumber()));
        } else if (kind == QLatin1String("force")) {
            // Runge-Kutta evaluates the forces again at trial states; their
            // sums are shown in the acceleration rows, the forces only once.
            if (e.property(QStringLiteral("evaluation")).toInt() > 1)
                continue;
            const QString name = e.property(QStringLiteral("name")).toString();
            row.kind = StepApartRow::Kind::Force;
            row.stage = tr("Force: %1 adds its acceleration").arg(name);
            row.code = codeLines(findFunction(pieces, name), QStringLiteral(R"(acc\[\w+\]\.[xy]\s*=[^=])"));
            row.hasAcceleration = true;
            row.ownAx = e.property(QStringLiteral("own")).property(QStringLiteral("x")).toNumber();
            row.ownAy = e.property(QStringLiteral("own")).property(QStringLiteral("y")).toNumber();
            row.ax = e.property(QStringLiteral("acc")).property(QStringLiteral("x")).toNumber();
            row.ay = e.property(QStringLiteral("acc")).property(QStringLiteral("y")).toNumber();
            row.note = tr("its own part: (%1, %2) px/s²").arg(full(row.ownAx), full(row.ownAy));
        } else if (kind == QLatin1String("acceleration")) {
            evaluations = e.property(QStringLiteral("evaluation")).toInt();
            const bool trial = e.property(QStringLiteral("trial")).toBool();
            row.kind = StepApartRow::Kind::Acceleration;
            row.stage = evaluations == 1 && !trial ? tr("Acceleration: all the forces added up")
                                                   : tr("Acceleration k%1, at a trial state (Runge-Kutta)").arg(evaluations);
            row.code = codeLines(accelerations, QStringLiteral(R"(force\(world)"));
            row.hasAcceleration = true;
            row.ax = e.property(QStringLiteral("acc")).property(QStringLiteral("x")).toNumber();
            row.ay = e.property(QStringLiteral("acc")).property(QStringLiteral("y")).toNumber();
            if (script.global(QStringLiteral("forces")).property(QStringLiteral("length")).toInt() == 0)
                row.note = tr("no force is switched on: the acceleration stays 0");
        } else if (kind == QLatin1String("move")) {
            // The move's lines for one ball run one after the other, so the
            // ball between them holds the new velocity and the old position
            // (or the other way round, in the order the lines are written).
            const QJSValue after = e.property(QStringLiteral("after"));
            StepApartRow velocity = row;
            velocity.kind = StepApartRow::Kind::Velocity;
            velocity.stage = tr("Velocity changes");
            velocity.code = codeLines(move, QStringLiteral(R"(b\.v[xy]\s*=[^=])"));
            StepApartRow position = row;
            position.kind = StepApartRow::Kind::Position;
            position.stage = tr("Position moves");
            position.code = codeLines(move, QStringLiteral(R"(b\.[xy]\s*=[^=])"));
            const bool velocityFirst = velocityLine >= 0 && (positionLine < 0 || velocityLine < positionLine);
            if (velocityFirst) {
                velocity.vx = after.property(QStringLiteral("vx")).toNumber();
                velocity.vy = after.property(QStringLiteral("vy")).toNumber();
                setBall(position, after);
                m_rows << velocity << position;
                last = position;
            } else {
                position.x = after.property(QStringLiteral("x")).toNumber();
                position.y = after.property(QStringLiteral("y")).toNumber();
                setBall(velocity, after);
                m_rows << position << velocity;
                last = velocity;
            }
            if (evaluations > 1)
                m_rows.last().note = tr("with the %1 accelerations above, weighted 1, 2, 2, 1").arg(evaluations);
            continue;
        } else if (kind == QLatin1String("rule")) {
            continue; // the rule's end says what it did
        } else if (kind == QLatin1String("ruleEnd")) {
            const QString name = e.property(QStringLiteral("name")).toString();
            if (name == QLatin1String("collide"))
                continue; // its detection, response and push-apart have rows of their own
            setBall(row, e.property(QStringLiteral("after")));
            row.kind = StepApartRow::Kind::Rule;
            row.stage = ruleWords(name);
            row.code = codeLines(findFunction(pieces, name), QStringLiteral(R"(^\s*b(\.\w+|\[[^\]]+\])\s*=[^=])"));
            const bool same = sameBits(row.x, last.x) && sameBits(row.y, last.y) && sameBits(row.vx, last.vx)
                              && sameBits(row.vy, last.vy);
            if (same)
                row.note = name == QLatin1String("bounceOnWalls") ? tr("no wall touched: nothing changed")
                                                                  : tr("nothing changed for this ball");
        } else if (kind == QLatin1String("detect")) {
            setBall(row, e.property(QStringLiteral("after")));
            row.kind = StepApartRow::Kind::Detection;
            row.stage = tr("Detection: which balls touch?");
            row.code = codeLines(findFunction(pieces, QStringLiteral("findContacts")), QStringLiteral(R"(contacts\.push)"));
            const QJSValue pairs = e.property(QStringLiteral("pairs"));
            QStringList words;
            for (int p = 0; p < pairs.property(QStringLiteral("length")).toInt(); ++p) {
                const QJSValue pair = pairs.property(static_cast<quint32>(p));
                row.pairs << qMakePair(pair.property(0).toInt(), pair.property(1).toInt());
                words << tr("ball %1 and ball %2").arg(row.pairs.last().first).arg(row.pairs.last().second);
            }
            row.note = words.isEmpty() ? tr("no ball touches ball %1 (%2 touching pairs in all)")
                                             .arg(ball)
                                             .arg(e.property(QStringLiteral("count")).toInt())
                                       : tr("touching: %1").arg(words.join(QStringLiteral(", ")));
        } else if (kind == QLatin1String("respond") || kind == QLatin1String("push")) {
            const bool respond = kind == QLatin1String("respond");
            const QJSValue before = e.property(QStringLiteral("before"));
            setBall(row, e.property(QStringLiteral("after")));
            row.other = e.property(QStringLiteral("other")).toInt();
            row.kind = respond ? StepApartRow::Kind::Response : StepApartRow::Kind::PushApart;
            if (respond) {
                row.stage = tr("Response with ball %1: the velocities change").arg(row.other);
                row.code = codeLines(findFunction(pieces, QStringLiteral("respond")),
                                     QStringLiteral(R"(^\s*[ab]\.v[xy]\s*=[^=])"));
                const double dvx = row.vx - before.property(QStringLiteral("vx")).toNumber();
                const double dvy = row.vy - before.property(QStringLiteral("vy")).toNumber();
                row.note = dvx == 0 && dvy == 0 ? tr("they are moving apart already: no change")
                                                : tr("Δvx = %1 px/s, Δvy = %2 px/s").arg(full(dvx), full(dvy));
            } else {
                row.stage = tr("Push-apart from ball %1: out of each other").arg(row.other);
                row.code = codeLines(findFunction(pieces, QStringLiteral("pushApart")),
                                     QStringLiteral(R"([ab]\.[xy]\s*=[^=])"));
                row.note = tr("overlap %1 px; Δx = %2 px, Δy = %3 px")
                               .arg(full(e.property(QStringLiteral("depth")).toNumber()),
                                    full(row.x - before.property(QStringLiteral("x")).toNumber()),
                                    full(row.y - before.property(QStringLiteral("y")).toNumber()));
            }
        } else {
            continue;
        }
        m_rows << row;
        last = row;
    }

    // The check: the script's ball after the whole step against the engine's.
    sim::World copy = world;
    copy.step();
    const ScriptBall s = script.ball(ball);
    StepApartRow check;
    check.kind = StepApartRow::Kind::Check;
    check.subStep = subSteps - 1;
    check.stage = tr("Check: the script's step against the engine's (C++)");
    check.x = s.x;
    check.y = s.y;
    check.vx = s.vx;
    check.vy = s.vy;
    const auto& engine = copy.balls();
    const double ex = engine.position(0, ball), ey = engine.position(1, ball);
    const double evx = engine.velocity(0, ball), evy = engine.velocity(1, ball);
    check.ok = sameBits(s.x, ex) && sameBits(s.y, ey) && sameBits(s.vx, evx) && sameBits(s.vy, evy);
    check.note = check.ok ? tr("matches the engine bit for bit")
                          : tr("differs from the engine by Δx = %1, Δy = %2 px, Δvx = %3, Δvy = %4 px/s")
                                .arg(full(s.x - ex), full(s.y - ey), full(s.vx - evx), full(s.vy - evy));
    m_rows << check;
}

QString StepApartDock::shownText() const
{
    if (!m_message.isEmpty())
        return m_message;
    return m_view->toPlainText();
}

void StepApartDock::render()
{
    const sim::World& world = m_controller->world();
    if (!m_message.isEmpty()) {
        m_title->setText(tr("One step, taken apart"));
        const bool error = !m_controller->isPlaying();
        m_view->setHtml(QStringLiteral("<p style='color:%1'>%2</p>")
                            .arg(error ? QStringLiteral("#c62828") : QStringLiteral("#555555"), m_message.toHtmlEscaped()));
        return;
    }
    m_title->setText(tr("Ball %1, step %2 → %3, in the order the JavaScript runs it. Changed values are highlighted.")
                         .arg(m_ball)
                         .arg(world.stepCount())
                         .arg(world.stepCount() + 1));
    const QString mono = QFontDatabase::systemFont(QFontDatabase::FixedFont).family();
    QString html;
    const StepApartRow* previous = nullptr;
    const int only = m_subStep->value() - 1; // -1: all
    for (const StepApartRow& row : m_rows) {
        if (only >= 0 && row.subStep != only && row.kind != StepApartRow::Kind::Check)
            continue;
        const bool heading = row.kind == StepApartRow::Kind::SubStep;
        const bool check = row.kind == StepApartRow::Kind::Check;
        QString colour = heading ? QStringLiteral("#1565c0") : QStringLiteral("#000000");
        if (check)
            colour = row.ok ? QStringLiteral("#2e7d32") : QStringLiteral("#c62828");
        html += QStringLiteral("<p style='margin-top:10px; margin-bottom:2px; color:%1'><b>%2</b></p>")
                    .arg(colour, row.stage.toHtmlEscaped());
        for (const QString& line : row.code)
            html += QStringLiteral("<div style='font-family:\"%1\"; color:#6a1b9a; white-space:pre-wrap'>%2</div>")
                        .arg(mono, line.toHtmlEscaped());
        auto cell = [&](const char* name, double v, double before, const char* unit) {
            const bool changed = previous && !heading && !sameBits(v, before);
            return QStringLiteral("<td>%1 =</td><td align='right' style='font-family:\"%2\"; %3'>%4</td><td>%5</td>")
                .arg(QLatin1String(name), mono,
                     changed ? QStringLiteral("background-color:#fff176; font-weight:bold") : QString(), full(v),
                     QString::fromUtf8(unit));
        };
        const StepApartRow& p = previous ? *previous : row;
        html += QStringLiteral("<table cellspacing='0' cellpadding='2'>");
        if (row.hasAcceleration) {
            // The forces only add to the acceleration (it starts at 0); the
            // ball itself does not move until the velocity and position rows.
            const bool before = previous && previous->hasAcceleration;
            html += QStringLiteral("<tr>%1</tr><tr>%2</tr>")
                        .arg(cell("ax", row.ax, before ? p.ax : 0.0, "px/s²"),
                             cell("ay", row.ay, before ? p.ay : 0.0, "px/s²"));
        } else {
            html += QStringLiteral("<tr>%1</tr><tr>%2</tr><tr>%3</tr><tr>%4</tr>")
                        .arg(cell("x", row.x, p.x, "px"), cell("y", row.y, p.y, "px"),
                             cell("vx", row.vx, p.vx, "px/s"), cell("vy", row.vy, p.vy, "px/s"));
        }
        html += QStringLiteral("</table>");
        if (!row.note.isEmpty())
            html += QStringLiteral("<div style='color:%1'>%2</div>").arg(check ? colour : QStringLiteral("#555555"),
                                                                           row.note.toHtmlEscaped());
        previous = &row;
    }
    m_view->setHtml(html);
}

} // namespace forcelab
