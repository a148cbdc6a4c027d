#include "ui/script/script_world.h"

#include "ui/script/script_watchdog.h"

#include "sim/integrators/integrator_info.h"

#include <sstream>
#include <string>
#include <vector>

namespace forcelab {

namespace {

QString scaleName(sim::ForceScale s)
{
    switch (s) {
    case sim::ForceScale::None:
        return QStringLiteral("none");
    case sim::ForceScale::Radius:
        return QStringLiteral("radius");
    case sim::ForceScale::Mass:
        return QStringLiteral("mass");
    }
    return QStringLiteral("none");
}

QString windName(sim::WindMode m)
{
    switch (m) {
    case sim::WindMode::Off:
        return QStringLiteral("off");
    case sim::WindMode::Random:
        return QStringLiteral("random");
    case sim::WindMode::Smoothed:
        return QStringLiteral("smoothed");
    case sim::WindMode::Noise:
        return QStringLiteral("noise");
    case sim::WindMode::Pointer:
        return QStringLiteral("pointer");
    }
    return QStringLiteral("off");
}

QString wallModelName(sim::WallModel m)
{
    switch (m) {
    case sim::WallModel::Clamp:
        return QStringLiteral("clamp");
    case sim::WallModel::Mirror:
        return QStringLiteral("mirror");
    case sim::WallModel::Exact:
        return QStringLiteral("exact");
    case sim::WallModel::Reverse:
        return QStringLiteral("reverse");
    }
    return QStringLiteral("clamp");
}

} // namespace

QString ScriptError::text() const
{
    QString where = file;
    if (line > 0)
        where += QStringLiteral(":%1").arg(line);
    if (column > 0)
        where += QStringLiteral(":%1").arg(column);
    return where.isEmpty() ? message : where + QStringLiteral(": ") + message;
}

ScriptWorld::ScriptWorld()
    : m_watchdog(std::make_unique<ScriptWatchdog>(&m_engine))
{
    // No installExtensions: the script sees plain ECMAScript and the two
    // objects handed to it, nothing of the program or the machine.
}

ScriptWorld::~ScriptWorld() = default;

std::optional<ScriptError> ScriptWorld::errorOf(const QJSValue& result, const QString& file, bool interrupted) const
{
    if (interrupted)
        return ScriptError{QStringLiteral("stopped after %1 s: the code ran too long (an endless loop?)")
                               .arg(static_cast<double>(m_limit.count()) / 1000.0),
                           file, 0, 0};
    if (!result.isError())
        return std::nullopt;
    ScriptError e;
    e.message = result.toString();
    const QJSValue fileName = result.property(QStringLiteral("fileName"));
    e.file = fileName.isUndefined() || fileName.toString().isEmpty() ? file : fileName.toString();
    if (e.file.startsWith(QStringLiteral("file:"))) // the engine makes a URL of the name
        e.file = e.file.mid(5);
    e.line = result.property(QStringLiteral("lineNumber")).toInt();
    const QJSValue column = result.property(QStringLiteral("columnNumber"));
    e.column = column.isUndefined() ? 0 : column.toInt();
    return e;
}

std::optional<ScriptError> ScriptWorld::evaluate(const QString& code, const QString& file)
{
    m_watchdog->arm(m_limit);
    QStringList stack; // "function:line:column:file" per frame; the column is known for syntax errors
    const QJSValue result = m_engine.evaluate(code, file, 1, &stack);
    const bool interrupted = m_watchdog->disarm() && result.isError();
    std::optional<ScriptError> error = errorOf(result, file, interrupted);
    if (error && error->column == 0 && !stack.isEmpty()) {
        const QStringList parts = stack.front().split(QLatin1Char(':'));
        if (parts.size() >= 3 && parts[1].toInt() == error->line && parts[2].toInt() > 0)
            error->column = parts[2].toInt();
    }
    return error;
}

QJSValue ScriptWorld::settingsObject(const sim::WorldSettings& s, const sim::SpawnSettings& spawn)
{
    QJSEngine& js = m_engine;
    QJSValue w = js.newObject();
    w.setProperty(QStringLiteral("width"), s.box.width);
    w.setProperty(QStringLiteral("height"), s.box.height);
    w.setProperty(QStringLiteral("dt"), s.time.dt);
    w.setProperty(QStringLiteral("substeps"), s.time.substeps);
    w.setProperty(QStringLiteral("perFrame"), s.time.perFrame);
    w.setProperty(QStringLiteral("integrator"), QString::fromUtf8(sim::integratorInfo(s.time.integrator).name.data(),
                                                                  static_cast<qsizetype>(sim::integratorInfo(s.time.integrator).name.size())));
    w.setProperty(QStringLiteral("seed"), QString::number(s.time.seed)); // a string: BigInt takes all 64 bits
    w.setProperty(QStringLiteral("time"), 0.0);
    w.setProperty(QStringLiteral("timeCarry"), 0.0);
    QJSValue walls = js.newObject();
    walls.setProperty(QStringLiteral("left"), s.walls.left);
    walls.setProperty(QStringLiteral("right"), s.walls.right);
    walls.setProperty(QStringLiteral("top"), s.walls.top);
    walls.setProperty(QStringLiteral("bottom"), s.walls.bottom);
    walls.setProperty(QStringLiteral("middle"), s.walls.middle);
    walls.setProperty(QStringLiteral("centreOnly"), s.walls.centreOnly);
    walls.setProperty(QStringLiteral("model"), wallModelName(s.walls.model));
    walls.setProperty(QStringLiteral("restitution"), s.walls.restitution);
    w.setProperty(QStringLiteral("walls"), walls);
    QJSValue gravity = js.newObject();
    gravity.setProperty(QStringLiteral("x"), s.gravity.g.x());
    gravity.setProperty(QStringLiteral("y"), s.gravity.g.y());
    w.setProperty(QStringLiteral("gravity"), gravity);
    QJSValue drag = js.newObject();
    drag.setProperty(QStringLiteral("law"), s.drag.law == sim::DragLaw::Linear ? QStringLiteral("linear")
                                                                                : QStringLiteral("quadratic"));
    drag.setProperty(QStringLiteral("k"), s.drag.k);
    drag.setProperty(QStringLiteral("scale"), scaleName(s.drag.scale));
    w.setProperty(QStringLiteral("drag"), drag);
    QJSValue wind = js.newObject();
    wind.setProperty(QStringLiteral("mode"), windName(s.wind.mode));
    wind.setProperty(QStringLiteral("strength"), s.wind.strength);
    wind.setProperty(QStringLiteral("scale"), scaleName(s.wind.scale));
    wind.setProperty(QStringLiteral("smoothedStep"), s.wind.smoothedStep);
    wind.setProperty(QStringLiteral("frequency"), s.wind.noiseFrequency);
    w.setProperty(QStringLiteral("wind"), wind);
    QJSValue random = js.newObject();
    random.setProperty(QStringLiteral("fixed"), s.randomAccel.fixed);
    random.setProperty(QStringLiteral("strength"), s.randomAccel.strength);
    random.setProperty(QStringLiteral("uncentred"), s.randomAccel.uncentred);
    w.setProperty(QStringLiteral("randomAccel"), random);
    QJSValue point = js.newObject();
    point.setProperty(QStringLiteral("kind"), s.point.kind == sim::PointKind::Attract ? QStringLiteral("attract")
                                                                                      : QStringLiteral("repel"));
    point.setProperty(QStringLiteral("x"), s.point.position.x());
    point.setProperty(QStringLiteral("y"), s.point.position.y());
    point.setProperty(QStringLiteral("strength"), s.point.strength);
    point.setProperty(QStringLiteral("maxAccel"), s.point.maxAccel);
    point.setProperty(QStringLiteral("scale"), scaleName(s.point.scale));
    point.setProperty(QStringLiteral("unnormalised"), s.point.unnormalised);
    w.setProperty(QStringLiteral("point"), point);
    QJSValue spring = js.newObject();
    spring.setProperty(QStringLiteral("x"), s.spring.anchor.x());
    spring.setProperty(QStringLiteral("y"), s.spring.anchor.y());
    spring.setProperty(QStringLiteral("k"), s.spring.k);
    w.setProperty(QStringLiteral("spring"), spring);
    QJSValue mutual = js.newObject();
    mutual.setProperty(QStringLiteral("G"), s.mutualGravity.G);
    mutual.setProperty(QStringLiteral("softening"), s.mutualGravity.softening);
    w.setProperty(QStringLiteral("mutualGravity"), mutual);
    QJSValue magnetic = js.newObject();
    magnetic.setProperty(QStringLiteral("B"), s.magnetic.B);
    w.setProperty(QStringLiteral("magnetic"), magnetic);
    QJSValue limit = js.newObject();
    limit.setProperty(QStringLiteral("max"), s.speedLimit.max);
    w.setProperty(QStringLiteral("speedLimit"), limit);
    QJSValue homing = js.newObject();
    homing.setProperty(QStringLiteral("strength"), s.homing.strength);
    w.setProperty(QStringLiteral("homing"), homing);
    QJSValue pointerForce = js.newObject();
    pointerForce.setProperty(QStringLiteral("strength"), s.pointer.strength);
    pointerForce.setProperty(QStringLiteral("maxAccel"), s.pointer.maxAccel);
    w.setProperty(QStringLiteral("pointerForce"), pointerForce);
    QJSValue collisions = js.newObject();
    collisions.setProperty(QStringLiteral("restitution"), s.collisions.restitution);
    w.setProperty(QStringLiteral("collisions"), collisions);
    w.setProperty(QStringLiteral("pointer"), QJSValue(QJSValue::NullValue)); // no pointer over the box
    QJSValue sp = js.newObject();
    sp.setProperty(QStringLiteral("perStep"), spawn.perStep);
    sp.setProperty(QStringLiteral("maxCount"), spawn.maxCount);
    sp.setProperty(QStringLiteral("minRadius"), spawn.minRadius);
    sp.setProperty(QStringLiteral("maxRadius"), spawn.maxRadius);
    sp.setProperty(QStringLiteral("minSpeed"), spawn.minSpeed);
    sp.setProperty(QStringLiteral("maxSpeed"), spawn.maxSpeed);
    sp.setProperty(QStringLiteral("horizontal"), spawn.horizontal);
    sp.setProperty(QStringLiteral("fullyInside"), spawn.fullyInside);
    sp.setProperty(QStringLiteral("seed"), QString::number(spawn.seed));
    sp.setProperty(QStringLiteral("colours"),
                   static_cast<int>(spawn.palette.empty() ? sim::defaultPalette().size() : spawn.palette.size()));
    w.setProperty(QStringLiteral("spawn"), sp);
    return w;
}

QJSValue ScriptWorld::ballsArray(const sim::BallState& balls)
{
    QJSValue array = m_engine.newArray(static_cast<uint>(balls.size()));
    for (int i = 0; i < balls.size(); ++i) {
        QJSValue b = m_engine.newObject();
        b.setProperty(QStringLiteral("x"), balls.position(0, i));
        b.setProperty(QStringLiteral("y"), balls.position(1, i));
        b.setProperty(QStringLiteral("vx"), balls.velocity(0, i));
        b.setProperty(QStringLiteral("vy"), balls.velocity(1, i));
        b.setProperty(QStringLiteral("r"), balls.radius[i]);
        b.setProperty(QStringLiteral("m"), balls.mass[i]);
        b.setProperty(QStringLiteral("q"), balls.charge[i]);
        b.setProperty(QStringLiteral("hx"), balls.home(0, i)); // where homing pulls it
        b.setProperty(QStringLiteral("hy"), balls.home(1, i));
        array.setProperty(static_cast<quint32>(i), b);
    }
    return array;
}

std::optional<ScriptError> ScriptWorld::load(const sim::WorldSettings& settings, const sim::BallState& balls,
                                             const sim::SpawnSettings& spawn)
{
    const ScriptPieces pieces = scriptPiecesFor(settings, spawn);
    if (!pieces.missing.isEmpty())
        return ScriptError{QStringLiteral("no JavaScript yet for %1").arg(pieces.missing.join(QStringLiteral(", "))),
                           {}, 0, 0};
    return load(pieces.files, settings, balls, spawn);
}

std::optional<ScriptError> ScriptWorld::load(const QStringList& pieces, const sim::WorldSettings& settings,
                                             const sim::BallState& balls, const sim::SpawnSettings& spawn,
                                             const QString& extra, const QMap<QString, QString>& replaced)
{
    for (const QString& name : pieces) {
        const auto own = replaced.constFind(name);
        const QString source = own != replaced.cend() ? *own : scriptPieceSource(name);
        if (source.isEmpty() && own == replaced.cend())
            return ScriptError{QStringLiteral("no piece named %1").arg(name), name, 0, 0};
        if (auto error = evaluate(source, name))
            return error;
    }
    if (!extra.isEmpty())
        if (auto error = evaluate(extra, QStringLiteral("extra.js")))
            return error;
    m_world = settingsObject(settings, spawn);
    m_balls = ballsArray(balls);
    m_step = m_engine.globalObject().property(QStringLiteral("step"));
    if (!m_step.isCallable())
        return ScriptError{QStringLiteral("the code has no function step(world, balls)"), {}, 0, 0};
    return std::nullopt;
}

namespace {

// A generator's state as the script's randomFromState(words, index) takes it.
// libstdc++ writes the 312 words as it keeps them and then how many it has
// used; the standard's form is the last 312 numbers in order, which is the
// same state with all of them used.
QString randomStateCall(const std::mt19937_64& generator)
{
    std::ostringstream text;
    text << generator;
    std::istringstream in(text.str());
    std::vector<std::string> words;
    for (std::string word; in >> word;)
        words.push_back(word);
    int index = 312;
    if (words.size() == 313) {
        index = std::stoi(words.back());
        words.pop_back();
    }
    QString call = QStringLiteral("randomFromState([");
    for (std::size_t i = 0; i < words.size(); ++i)
        call += (i ? QStringLiteral(",\"") : QStringLiteral("\"")) + QString::fromStdString(words[i]) + QStringLiteral("\"");
    return call + QStringLiteral("], %1)").arg(index);
}

} // namespace

std::optional<ScriptError> ScriptWorld::piecesFor(const sim::World& world, QStringList& files)
{
    const ScriptPieces pieces = scriptPiecesFor(world.settings(), world.spawn());
    if (!pieces.missing.isEmpty())
        return ScriptError{QStringLiteral("no JavaScript yet for %1").arg(pieces.missing.join(QStringLiteral(", "))),
                           {}, 0, 0};
    files = pieces.files;
    return std::nullopt;
}

std::optional<ScriptError> ScriptWorld::loadFrom(const sim::World& world, const QString& extra,
                                                 const QMap<QString, QString>& replaced)
{
    QStringList files;
    if (auto error = piecesFor(world, files))
        return error;
    if (auto error = load(files, world.settings(), world.balls(), world.spawn(), extra, replaced))
        return error;
    m_world.setProperty(QStringLiteral("time"), world.time());
    m_world.setProperty(QStringLiteral("timeCarry"), world.timeCarry());
    if (!m_engine.globalObject().property(QStringLiteral("randomFromState")).isCallable())
        return std::nullopt; // no piece draws random numbers
    // The generators as the engine has them, where the pieces would make them
    // from the seed on their first draw.
    auto generator = [this](const std::mt19937_64& g) { return m_engine.evaluate(randomStateCall(g)); };
    QJSValue random = m_world.property(QStringLiteral("randomAccel"));
    random.setProperty(QStringLiteral("rng"), generator(world.accelGenerator()));
    const sim::Matrix2X& draws = world.randomDraws();
    QJSValue values = m_engine.newArray(static_cast<uint>(draws.cols()));
    for (Eigen::Index i = 0; i < draws.cols(); ++i) {
        QJSValue v = m_engine.newObject();
        v.setProperty(QStringLiteral("x"), draws(0, i));
        v.setProperty(QStringLiteral("y"), draws(1, i));
        values.setProperty(static_cast<quint32>(i), v);
    }
    random.setProperty(QStringLiteral("values"), values);
    QJSValue wind = m_world.property(QStringLiteral("wind"));
    wind.setProperty(QStringLiteral("rng"), generator(world.windGenerator().generator()));
    wind.setProperty(QStringLiteral("value"), world.windGenerator().value());
    const QJSValue makeNoise = m_engine.globalObject().property(QStringLiteral("makeNoise"));
    if (makeNoise.isCallable())
        wind.setProperty(QStringLiteral("slopes"), makeNoise.call({m_world.property(QStringLiteral("seed"))}));
    m_world.property(QStringLiteral("spawn")).setProperty(QStringLiteral("rng"), generator(world.spawnGenerator()));
    return std::nullopt;
}

QJSValue ScriptWorld::global(const QString& name) const
{
    return m_engine.globalObject().property(name);
}

std::optional<ScriptError> ScriptWorld::step()
{
    if (!m_step.isCallable())
        return ScriptError{QStringLiteral("nothing loaded"), {}, 0, 0};
    m_watchdog->arm(m_limit);
    const QJSValue result = m_step.call({m_world, m_balls});
    const bool interrupted = m_watchdog->disarm() && result.isError();
    return errorOf(result, QStringLiteral("step"), interrupted);
}

void ScriptWorld::setPointer(const sim::PointerInput& pointer)
{
    if (!pointer.inside) {
        m_world.setProperty(QStringLiteral("pointer"), QJSValue(QJSValue::NullValue));
        return;
    }
    QJSValue p = m_engine.newObject();
    p.setProperty(QStringLiteral("inside"), true);
    p.setProperty(QStringLiteral("pressed"), pointer.pressed);
    p.setProperty(QStringLiteral("x"), pointer.position.x());
    p.setProperty(QStringLiteral("y"), pointer.position.y());
    m_world.setProperty(QStringLiteral("pointer"), p);
}

int ScriptWorld::ballCount() const
{
    return m_balls.property(QStringLiteral("length")).toInt();
}

ScriptBall ScriptWorld::ball(int i) const
{
    const QJSValue b = m_balls.property(static_cast<quint32>(i));
    return {b.property(QStringLiteral("x")).toNumber(),  b.property(QStringLiteral("y")).toNumber(),
            b.property(QStringLiteral("vx")).toNumber(), b.property(QStringLiteral("vy")).toNumber(),
            b.property(QStringLiteral("r")).toNumber(),  b.property(QStringLiteral("m")).toNumber()};
}

} // namespace forcelab
