// forcelab-cli sweep: a work-precision study. Every integrator runs reference
// problems with known answers at a range of time steps (and of tolerances for
// the adaptive ones); each run reports its error against the closed form and
// its cost. Output: a table, optional CSV, optional log-log chart (QPainter on
// a QImage), the fitted orders of convergence, and the long-run energy
// behaviour of the symplectic methods next to rk4's drift.

#include "cli_commands.h"

#include "sim/integrator_info.h"
#include "sim/kepler.h"
#include "sim/names.h"
#include "sim/work_precision.h"
#include "sim/world.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QString>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

using namespace forcelab::sim;

namespace forcelab::cli {
namespace {

constexpr double kPi = std::numbers::pi;

// ---------------------------------------------------------------------------
// The reference problems. Each builds a scene for a time step and knows the
// exact positions at its end time and, when it has one, the exact energy.

struct Problem {
    std::string name;
    std::string what;
    double endTime = 1.0;                                 // s, a multiple of every dt swept
    double length = 1.0;                                  // px, the problem's size (for "relative" errors)
    std::function<Scene()> scene;                         // integrator and dt are set by the sweep
    std::function<Matrix2X(double t)> exact;              // exact positions of all balls at t
    std::function<double(const World&)> energyError;      // |E − E_exact| / |E_exact| now; null: none
};

// The reference problems' balls have mass 1 unless they say otherwise.
Ball makeBall(double x, double y, double vx, double vy, double r = 10.0, double mass = 1.0)
{
    return ballAt(x, y, vx, vy, r, mass);
}


// Kepler's problem (sim/kepler.h): a = 100 px, period 1 s, starting at
// periapsis. The end is 5/16 of an orbit past the whole orbits: at whole
// orbits some errors cancel.
Problem kepler(double e, int orbits)
{
    KeplerOrbit orbit;
    orbit.e = e;
    std::ostringstream name;
    name << "kepler-e" << e << "-" << orbits;
    Problem p;
    p.name = name.str();
    p.what = "Kepler orbit, e = " + std::to_string(e).substr(0, 3) + ", " + std::to_string(orbits) + " orbits";
    p.endTime = orbits + 5.0 / 16.0;
    p.length = orbit.a;
    p.scene = [=] {
        Scene s = orbit.scene(IntegratorKind::SemiImplicitEuler, 1.0 / 60); // integrator and dt: set by the sweep
        s.settings.box = BoxSettings{600.0, 400.0};
        return s;
    };
    p.exact = [=](double t) {
        Matrix2X x(2, 1);
        x.col(0) = orbit.position(t);
        return x;
    };
    const double energy = orbit.energyPerMass(); // the ball's mass is 1
    p.energyError = [=](const World& w) { return std::abs((w.energy().total() - energy) / energy); };
    return p;
}

// Falling from rest with linear drag: v = (g/k)(1 − e^(−kt)),
// y = y₀ + (g/k) t − (g/k²)(1 − e^(−kt)). No energy to conserve.
Problem dragFall()
{
    const double g = 980.0, k = 1.5, y0 = 0.0;
    Problem p;
    p.name = "drag";
    p.what = "free fall with linear drag, k = 1.5/s, 2 s";
    p.endTime = 2.0;
    p.length = g / (k * k);
    p.scene = [=] {
        Scene s = openScene({makeBall(100.0, y0, 0.0, 0.0)});
        s.settings.gravity = GravitySettings{true, Vec2(0.0, g)};
        s.settings.drag = DragSettings{true, DragLaw::Linear, k};
        return s;
    };
    p.exact = [=](double t) {
        Matrix2X x(2, 1);
        x.col(0) = Vec2(100.0, y0 + g / k * t - g / (k * k) * (1.0 - std::exp(-k * t)));
        return x;
    };
    return p;
}

// A spring to an anchor, ω = √k = 2 rad/s: an ellipse x = A cos ωt,
// y = (v₀/ω) sin ωt around the anchor. About 3.3 periods.
Problem spring()
{
    const double k = 4.0, w = 2.0, A = 100.0, v0 = 120.0;
    const Vec2 anchor(300.0, 200.0);
    Problem p;
    p.name = "spring";
    p.what = "spring (harmonic oscillator), omega = 2 rad/s, 3.3 periods";
    p.endTime = 10.3125;
    p.length = A;
    p.scene = [=] {
        Scene s = openScene({makeBall(anchor.x() + A, anchor.y(), 0.0, v0)});
        s.settings.spring = SpringSettings{true, anchor, k};
        return s;
    };
    p.exact = [=](double t) {
        Matrix2X x(2, 1);
        x.col(0) = anchor + Vec2(A * std::cos(w * t), v0 / w * std::sin(w * t));
        return x;
    };
    const double energy = 0.5 * v0 * v0 + 0.5 * k * A * A;
    p.energyError = [=](const World& wd) { return std::abs((wd.energy().total() - energy) / energy); };
    return p;
}

// Dropped from rest H = 300 px above the floor, exact walls, restitution e:
// after bounce k the ball rises to e^(2k) H. The energy error is the height
// the ball's energy would carry it to (floor gap + v²/2g) against e^(2k) H,
// with k the bounces counted so far.
Problem bounce()
{
    const double g = 980.0, H = 300.0, e = 0.8, r = 10.0, floorY = 400.0 - r;
    Problem p;
    p.name = "bounce";
    p.what = "ball bouncing, restitution 0.8, exact walls, 3.5 s";
    p.endTime = 3.5;
    p.length = H;
    p.scene = [=] {
        Scene s = openScene({makeBall(300.0, floorY - H, 0.0, 0.0, r)});
        s.settings.walls = WallSettings{false, false, false, true, WallModel::Exact, e};
        s.settings.gravity = GravitySettings{true, Vec2(0.0, g)};
        return s;
    };
    p.exact = [=](double t) {
        // Flight k (k = 0 the drop) starts at the floor with speed e^k u₀
        // upwards (k ≥ 1) and lasts 2 e^k u₀ / g.
        const double u0 = std::sqrt(2.0 * g * H);
        double start = std::sqrt(2.0 * H / g); // the first impact
        Matrix2X x(2, 1);
        if (t <= start) {
            x.col(0) = Vec2(300.0, floorY - H + 0.5 * g * t * t);
            return x;
        }
        double speed = e * u0;
        while (t > start + 2.0 * speed / g) {
            start += 2.0 * speed / g;
            speed *= e;
        }
        const double s = t - start;
        x.col(0) = Vec2(300.0, floorY - speed * s + 0.5 * g * s * s);
        return x;
    };
    p.energyError = [=](const World& w) {
        const double y = w.balls().position(1, 0), vy = w.balls().velocity(1, 0);
        const double height = (floorY - y) + vy * vy / (2.0 * g);
        const double expected = H * std::pow(e, 2.0 * static_cast<double>(w.totals().wallHits));
        return std::abs(height - expected) / expected;
    };
    return p;
}

// Two balls (masses 1 and 3) meet head-on, elastic 2D impulse response, no
// forces. They touch at t_c; afterwards v₁' = ((m₁−m₂)v₁ + 2m₂v₂)/(m₁+m₂) and
// v₂' = ((m₂−m₁)v₂ + 2m₁v₁)/(m₁+m₂). The energy (kinetic) must stay.
Problem twoBalls()
{
    const double m1 = 1.0, m2 = 3.0, r = 10.0;
    const Vec2 x1(150.0, 200.0), x2(400.0, 200.0), v1(130.0, 0.0), v2(-70.0, 0.0);
    Problem p;
    p.name = "two-balls";
    p.what = "two balls, masses 1 and 3, elastic head-on collision, 2 s";
    p.endTime = 2.0;
    p.length = 2.0 * r;
    p.scene = [=] {
        Scene s = openScene({makeBall(x1.x(), x1.y(), v1.x(), v1.y(), r, m1),
                             makeBall(x2.x(), x2.y(), v2.x(), v2.y(), r, m2)});
        s.settings.collisions.response = Response::Impulse2D;
        s.settings.collisions.restitution = 1.0;
        return s;
    };
    const double tc = ((x2.x() - x1.x()) - 2.0 * r) / (v1.x() - v2.x());
    const Vec2 w1 = ((m1 - m2) * v1 + 2.0 * m2 * v2) / (m1 + m2);
    const Vec2 w2 = ((m2 - m1) * v2 + 2.0 * m1 * v1) / (m1 + m2);
    p.exact = [=](double t) {
        Matrix2X x(2, 2);
        if (t <= tc) {
            x.col(0) = x1 + v1 * t;
            x.col(1) = x2 + v2 * t;
        } else {
            x.col(0) = x1 + v1 * tc + w1 * (t - tc);
            x.col(1) = x2 + v2 * tc + w2 * (t - tc);
        }
        return x;
    };
    const double energy = 0.5 * m1 * v1.squaredNorm() + 0.5 * m2 * v2.squaredNorm();
    p.energyError = [=](const World& w) { return std::abs((w.energy().kinetic - energy) / energy); };
    return p;
}

std::vector<Problem> allProblems(bool quick)
{
    std::vector<Problem> p{kepler(0.0, 10), kepler(0.5, 10)};
    if (!quick) {
        p.push_back(kepler(0.0, 100));
        p.push_back(kepler(0.5, 100));
    }
    p.push_back(dragFall());
    p.push_back(spring());
    p.push_back(bounce());
    p.push_back(twoBalls());
    return p;
}

// ---------------------------------------------------------------------------
// One run and its measurements.

struct Row {
    std::string problem;
    IntegratorKind integrator = IntegratorKind::Euler;
    double dt = 0.0;
    double tolerance = 0.0; // adaptive methods only; 0 otherwise
    std::int64_t steps = 0;
    std::int64_t evaluations = 0;
    double positionError = 0.0; // px, largest over the balls; inf when the run blew up
    double energyError = std::nan(""); // largest |ΔE/E| sampled at every step; NaN: no energy to check
    double wallMs = 0.0;               // median of the repeats, stepping only
    double nsPerStepBall = 0.0;
    bool blewUp = false;
};

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::optional<Row> runOne(const Problem& p, IntegratorKind kind, double dt, double tolerance, int repeats)
{
    Scene scene = p.scene();
    scene.settings.time.integrator = kind;
    scene.settings.time.dt = dt;
    if (tolerance > 0.0)
        scene.settings.time.tolerance = tolerance;
    if (validateSettings(scene.settings))
        return std::nullopt; // e.g. exact with a force that is not constant
    Row row;
    row.problem = p.name;
    row.integrator = kind;
    row.dt = dt;
    row.tolerance = tolerance;
    row.steps = static_cast<std::int64_t>(std::llround(p.endTime / dt));
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
        World world;
        if (world.reset(scene))
            return std::nullopt;
        const bool first = r == 0;
        double worstEnergy = 0.0;
        for (std::int64_t k = 0; k < row.steps && !world.halted(); ++k) {
            world.step();
            // The energy is sampled at every step, so many times inside each
            // orbit; the sampling is outside the timed step.
            if (first && p.energyError)
                worstEnergy = std::max(worstEnergy, p.energyError(world));
        }
        if (world.halted()) {
            row.blewUp = true;
            row.positionError = std::numeric_limits<double>::infinity();
            row.energyError = std::numeric_limits<double>::infinity();
            return row;
        }
        times.push_back(world.totals().seconds * 1e3);
        if (first) {
            row.evaluations = world.totals().forceEvaluations;
            const Matrix2X exact = p.exact(world.time());
            row.positionError = (world.balls().position - exact).colwise().norm().maxCoeff();
            if (p.energyError)
                row.energyError = worstEnergy;
        }
    }
    row.wallMs = median(times);
    row.nsPerStepBall = row.wallMs * 1e6 / static_cast<double>(row.steps) / static_cast<double>(scene.balls.size());
    return row;
}

// ---------------------------------------------------------------------------
// Fitted order: least-squares slope of log(error) against log(dt), over the
// runs in the asymptotic range: error above rounding (1e-10 of the problem's
// size) and below 1e-2 of it, where error ≈ C dt^p holds.

struct Fit {
    double order = std::nan("");
    int points = 0;
};

Fit fittedOrder(const std::vector<Row>& rows, const Problem& p, IntegratorKind kind)
{
    std::vector<double> dts, errors;
    for (const Row& r : rows) {
        if (r.problem != p.name || r.integrator != kind || r.tolerance > 0.0 || r.blewUp)
            continue;
        const double rel = r.positionError / p.length;
        if (!(rel > 1e-10 && rel < 1e-2))
            continue;
        dts.push_back(r.dt);
        errors.push_back(r.positionError);
    }
    Fit f;
    f.points = int(dts.size());
    if (f.points >= 3)
        f.order = sim::fittedOrder(dts, errors); // the workbench's convergence button fits the same way
    return f;
}

// ---------------------------------------------------------------------------
// The chart: error against force evaluations, log-log, one line per integrator.

QColor integratorColor(IntegratorKind k)
{
    static const QRgb colors[] = {0xd62728, 0xff7f0e, 0x2ca02c, 0x1f77b4, 0x9467bd, 0x8c564b, 0x7f7f7f, 0x111111};
    return QColor::fromRgb(colors[static_cast<int>(k) % 8]);
}

double floorLog(double v) { return std::floor(std::log10(v)); }
double ceilLog(double v) { return std::ceil(std::log10(v)); }

void drawPanel(QPainter& p, const QRectF& area, const Problem& problem, const std::vector<Row>& all)
{
    std::vector<const Row*> rows;
    for (const Row& r : all)
        if (r.problem == problem.name && !r.blewUp && r.evaluations > 0)
            rows.push_back(&r);
    // Exact results are drawn on the floor; an error beyond 100 times the
    // problem's size (the orbit is lost) is drawn on the ceiling.
    static constexpr double kErrorFloor = 1e-16;
    const double ceiling = std::pow(10.0, ceilLog(100.0 * problem.length));
    auto errorOf = [=](const Row* r) { return std::clamp(r->positionError, kErrorFloor, ceiling); };
    double xMin = 1e300, xMax = 0, yMin = 1e300, yMax = 0;
    for (const Row* r : rows) {
        xMin = std::min(xMin, double(r->evaluations));
        xMax = std::max(xMax, double(r->evaluations));
        yMin = std::min(yMin, errorOf(r));
        yMax = std::max(yMax, errorOf(r));
    }
    if (rows.empty()) {
        xMin = 1;
        xMax = 10;
        yMin = 1e-16;
        yMax = 1;
    }
    const double lx0 = floorLog(xMin), lx1 = std::max(ceilLog(xMax), lx0 + 1);
    const double ly0 = floorLog(yMin), ly1 = std::max(ceilLog(yMax), ly0 + 1);

    p.save(); // each panel starts from the same pen, brush and font
    p.fillRect(area, Qt::white);
    QFont font = p.font();
    font.setPixelSize(13);
    p.setFont(font);
    const QRectF plot = area.adjusted(78, 40, -170, -56);
    auto X = [&](double v) { return plot.left() + (std::log10(v) - lx0) / (lx1 - lx0) * plot.width(); };
    auto Y = [&](double v) { return plot.bottom() - (std::log10(v) - ly0) / (ly1 - ly0) * plot.height(); };

    // Grid and tick labels at every power of ten (every other one when crowded).
    const int yStep = ly1 - ly0 > 10 ? 2 : 1;
    p.setPen(QPen(QColor(0xdd, 0xe1, 0xe7), 1));
    for (int e = int(lx0); e <= int(lx1); ++e)
        p.drawLine(QPointF(X(std::pow(10.0, e)), plot.top()), QPointF(X(std::pow(10.0, e)), plot.bottom()));
    for (int e = int(ly0); e <= int(ly1); e += yStep)
        p.drawLine(QPointF(plot.left(), Y(std::pow(10.0, e))), QPointF(plot.right(), Y(std::pow(10.0, e))));
    p.setPen(Qt::black);
    p.setBrush(Qt::NoBrush);
    p.drawRect(plot);
    for (int e = int(lx0); e <= int(lx1); ++e)
        p.drawText(QRectF(X(std::pow(10.0, e)) - 30, plot.bottom() + 4, 60, 18), Qt::AlignHCenter | Qt::AlignTop,
                   QStringLiteral("1e%1").arg(e));
    for (int e = int(ly0); e <= int(ly1); e += yStep)
        p.drawText(QRectF(plot.left() - 64, Y(std::pow(10.0, e)) - 9, 58, 18), Qt::AlignRight | Qt::AlignVCenter,
                   QStringLiteral("1e%1").arg(e));
    p.drawText(QRectF(plot.left(), plot.bottom() + 26, plot.width(), 20), Qt::AlignHCenter,
               QStringLiteral("cost: force evaluations (log scale)"));
    p.save();
    p.translate(area.left() + 16, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2, -10, plot.height(), 20), Qt::AlignHCenter,
               QStringLiteral("position error at the end, px (log scale)"));
    p.restore();
    QFont title = font;
    title.setPixelSize(15);
    title.setBold(true);
    p.setFont(title);
    p.drawText(QRectF(plot.left(), area.top() + 8, plot.width() + 160, 24), Qt::AlignLeft,
               QString::fromStdString(problem.what));
    p.setFont(font);

    // One line per integrator (and per swept dt for the adaptive ones), in
    // order of cost, with a dot at each run.
    p.setRenderHint(QPainter::Antialiasing);
    int legendRow = 0;
    for (std::size_t k = 0; k < integratorNames().size(); ++k) {
        const auto kind = static_cast<IntegratorKind>(k);
        std::vector<const Row*> line;
        // Adaptive methods: their tolerance sweep at the outer step of 1/16 s.
        const bool adaptive = integratorInfo(kind).adaptive;
        for (const Row* r : rows)
            if (r->integrator == kind && (!adaptive || r->dt == 1.0 / 16))
                line.push_back(r);
        if (line.empty())
            continue;
        std::sort(line.begin(), line.end(), [](const Row* a, const Row* b) { return a->evaluations < b->evaluations; });
        const QColor color = integratorColor(kind);
        QPainterPath path;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const QPointF pt(X(double(line[i]->evaluations)), Y(errorOf(line[i])));
            i ? path.lineTo(pt) : path.moveTo(pt);
        }
        p.setPen(QPen(color, 2));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setBrush(color);
        for (const Row* r : line)
            p.drawEllipse(QPointF(X(double(r->evaluations)), Y(errorOf(r))), 3, 3);
        // Legend entry.
        const QPointF at(plot.right() + 16, plot.top() + 8 + 22 * legendRow++);
        p.drawLine(at, at + QPointF(24, 0));
        p.setPen(Qt::black);
        p.drawText(QRectF(at.x() + 30, at.y() - 9, 130, 18), Qt::AlignLeft | Qt::AlignVCenter,
                   QString::fromLatin1(toString(kind).data(), int(toString(kind).size())));
    }
    p.restore();
}

constexpr int kPanelWidth = 760;
constexpr int kPanelHeight = 480;

bool writeChart(const QString& file, const std::vector<Problem>& problems, const std::vector<Row>& rows)
{
    const int n = int(problems.size());
    const int columns = std::min(n, 2), lines = (n + columns - 1) / columns;
    QImage image(columns * kPanelWidth, lines * kPanelHeight, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    for (int i = 0; i < n; ++i)
        drawPanel(painter, QRectF((i % columns) * kPanelWidth, (i / columns) * kPanelHeight, kPanelWidth, kPanelHeight),
                  problems[i], rows);
    painter.end();
    return image.save(file, "PNG");
}

// ---------------------------------------------------------------------------

struct Options {
    bool quick = false;
    std::optional<std::string> problem;
    std::optional<std::string> csv;
    std::optional<std::string> png;
};

std::string sci(double v, int digits = 2)
{
    if (std::isnan(v))
        return "-";
    if (std::isinf(v))
        return "blew up";
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << v;
    return s.str();
}

} // namespace

void declareSweep(QCommandLineParser& p)
{
    p.addOptions({
        {QStringLiteral("problem"), QStringLiteral("Only this reference problem (default: all of them)."),
         QStringLiteral("NAME")},
        {QStringLiteral("quick"), QStringLiteral("Fewer steps, tolerances and repeats.")},
        {QStringLiteral("csv"), QStringLiteral("Also write every run to FILE."), QStringLiteral("FILE")},
        {QStringLiteral("png"), QStringLiteral("Also draw the error-against-cost chart to FILE."), QStringLiteral("FILE")},
    });
}

int sweepCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    Options o;
    o.quick = parser.isSet(QStringLiteral("quick"));
    if (parser.isSet(QStringLiteral("problem")))
        o.problem = valueOf(parser, "problem");
    if (parser.isSet(QStringLiteral("csv")))
        o.csv = valueOf(parser, "csv");
    if (parser.isSet(QStringLiteral("png")))
        o.png = valueOf(parser, "png");
    if (!parser.positionalArguments().isEmpty()) {
        err << "forcelab-cli sweep: takes no arguments besides its options\n";
        return 2;
    }

    std::vector<Problem> problems = allProblems(o.quick);
    if (o.problem) {
        std::vector<Problem> all = allProblems(false);
        std::vector<Problem> picked;
        std::string names;
        for (const Problem& p : all) {
            names += (names.empty() ? "" : ", ") + p.name;
            if (p.name == *o.problem)
                picked.push_back(p);
        }
        if (picked.empty()) {
            err << "forcelab-cli sweep: --problem: \"" << *o.problem << "\" is not one of " << names << "\n";
            return 2;
        }
        problems = picked;
    }

    // The sweep. Fixed-step methods at dt = 2^-k s, each over the range where
    // its error goes from visible to rounding (a first-order method needs far
    // smaller steps than a fourth-order one). The adaptive methods at their
    // default tolerance over a few outer steps, and over a range of
    // tolerances at an outer step of 1/16 s (the energy is still sampled 16
    // times an orbit; their own sub-steps are usually shorter).
    const int repeats = o.quick ? 1 : 5;
    const std::vector<double> tolerances = o.quick ? std::vector<double>{1e-3, 1e-6, 1e-9}
                                                   : std::vector<double>{1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-9, 1e-11};
    auto dtRange = [&](IntegratorKind k) -> std::pair<int, int> {
        switch (k) {
        case IntegratorKind::Euler:
            return o.quick ? std::pair{10, 14} : std::pair{8, 16};
        case IntegratorKind::SemiImplicitEuler:
        case IntegratorKind::Exact:
            return o.quick ? std::pair{8, 12} : std::pair{6, 14};
        case IntegratorKind::Verlet:
            return o.quick ? std::pair{7, 11} : std::pair{5, 13};
        case IntegratorKind::Rk45:
        case IntegratorKind::Ias15:
            return o.quick ? std::pair{3, 5} : std::pair{2, 7};
        default: // rk4, yoshida4
            return o.quick ? std::pair{5, 9} : std::pair{4, 11};
        }
    };
    constexpr double kAdaptiveDt = 1.0 / 16;
    constexpr double kDefaultTolerance = 1e-9;
    struct Job {
        const Problem* problem;
        IntegratorKind kind;
        double dt, tolerance;
    };
    std::vector<Job> jobs;
    for (const Problem& p : problems) {
        for (std::size_t k = 0; k < integratorNames().size(); ++k) {
            const auto kind = static_cast<IntegratorKind>(k);
            const bool adaptive = integratorInfo(kind).adaptive;
            const auto [from, to] = dtRange(kind);
            for (int e = from; e <= to; ++e)
                jobs.push_back({&p, kind, std::ldexp(1.0, -e), adaptive ? kDefaultTolerance : 0.0});
            if (adaptive)
                for (double tol : tolerances)
                    if (tol != kDefaultTolerance)
                        jobs.push_back({&p, kind, kAdaptiveDt, tol});
        }
    }

    const auto started = std::chrono::steady_clock::now();
    std::vector<Row> rows;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        // A progress bar on stderr, redrawn in place.
        const int width = 30, filled = int(width * j / jobs.size());
        err << "\rsweep [" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << j << "/"
            << jobs.size() << " " << jobs[j].problem->name << std::string(12, ' ') << std::flush;
        if (auto row = runOne(*jobs[j].problem, jobs[j].kind, jobs[j].dt, jobs[j].tolerance, repeats))
            rows.push_back(*row);
    }
    err << "\rsweep [" << std::string(30, '#') << "] " << jobs.size() << "/" << jobs.size() << " done in "
        << std::fixed << std::setprecision(1)
        << std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() << " s"
        << std::string(20, ' ') << "\n"
        << std::defaultfloat;

    // The table.
    out << "Work-precision sweep: position error at the end against the closed form, largest relative energy\n"
           "error sampled at every step, cost. Times are medians of "
        << repeats << " runs.\n";
    for (const Problem& p : problems) {
        out << "\n" << p.name << ": " << p.what << " (end t = " << p.endTime << " s)\n";
        out << std::left << std::setw(20) << "integrator" << std::right << std::setw(11) << "dt s" << std::setw(9)
            << "tol" << std::setw(11) << "evals" << std::setw(12) << "pos err px" << std::setw(12) << "max|dE/E|"
            << std::setw(11) << "ns/step" << std::setw(10) << "wall ms" << "\n";
        for (const Row& r : rows) {
            if (r.problem != p.name)
                continue;
            out << std::left << std::setw(20) << toString(r.integrator) << std::right << std::setw(11) << sci(r.dt, 1)
                << std::setw(9) << (r.tolerance > 0 ? sci(r.tolerance, 0) : "-") << std::setw(11)
                << (r.blewUp ? "-" : std::to_string(r.evaluations)) << std::setw(12) << sci(r.positionError)
                << std::setw(12) << sci(r.energyError) << std::setw(11)
                << (r.blewUp ? "-" : sci(r.nsPerStepBall)) << std::setw(10) << (r.blewUp ? "-" : sci(r.wallMs))
                << "\n";
        }
    }

    // Fitted orders: slope of log(error) against log(dt).
    out << "\nFitted order (slope of log error against log dt over the runs with 1e-10 < error / size < 1e-2):\n";
    out << std::left << std::setw(20) << "problem";
    // Every fixed-step method with an order to fit.
    std::vector<IntegratorKind> fixed;
    for (const IntegratorInfo& info : integrators())
        if (!info.adaptive && info.order > 0.0)
            fixed.push_back(info.kind);
    for (IntegratorKind k : fixed)
        out << std::right << std::setw(21) << std::string(toString(k)) + " (" +
                                                   std::to_string(int(theoreticalOrder(k))) + ")";
    out << "\n";
    for (const Problem& p : problems) {
        out << std::left << std::setw(20) << p.name << std::right;
        for (IntegratorKind k : fixed) {
            const Fit f = fittedOrder(rows, p, k);
            std::ostringstream cell;
            if (std::isnan(f.order))
                cell << "- (" << f.points << " pts)";
            else
                cell << std::fixed << std::setprecision(2) << f.order << " (" << f.points << " pts)";
            out << std::setw(21) << cell.str();
        }
        out << "\n";
    }

    // Long runs: the symplectic methods' energy error stays bounded, rk4's
    // grows in proportion to time.
    {
        const Problem p = kepler(0.5, 1000);
        const std::vector<int> marks = o.quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
        const double dt = 1.0 / 256;
        out << "\nEnergy over long runs, Kepler e = 0.5, dt = 1/256 s: largest |dE/E| up to each number of orbits\n";
        out << std::left << std::setw(20) << "integrator" << std::right;
        for (int m : marks)
            out << std::setw(14) << std::to_string(m) + " orbits";
        out << std::setw(12) << "growth" << "\n";
        for (IntegratorKind k : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Yoshida4,
                                 IntegratorKind::Rk4, IntegratorKind::Ias15}) {
            Scene s = p.scene();
            s.settings.time.integrator = k;
            s.settings.time.dt = dt;
            World world;
            world.reset(s);
            double worst = 0.0;
            std::vector<double> at;
            std::int64_t step = 0;
            for (int m : marks) {
                for (; step < std::int64_t(m) * 256; ++step) {
                    world.step();
                    worst = std::max(worst, p.energyError(world));
                }
                at.push_back(worst);
            }
            out << std::left << std::setw(20) << toString(k) << std::right;
            for (double v : at)
                out << std::setw(14) << sci(v);
            out << std::setw(11) << std::fixed << std::setprecision(1) << at.back() / at.front() << "x"
                << std::defaultfloat << "\n";
        }
    }

    if (o.csv) {
        std::ofstream f(*o.csv);
        if (!f) {
            err << "forcelab-cli sweep: --csv: cannot write '" << *o.csv << "'\n";
            return 2;
        }
        f << "problem,integrator,dt,tolerance,steps,force_evaluations,position_error,energy_error,wall_ms,"
             "ns_per_step_per_ball,blew_up\n";
        f << std::setprecision(6);
        for (const Row& r : rows) {
            f << r.problem << "," << toString(r.integrator) << "," << r.dt << "," << r.tolerance << "," << r.steps
              << "," << r.evaluations << "," << r.positionError << ",";
            if (!std::isnan(r.energyError))
                f << r.energyError;
            f << "," << r.wallMs << "," << r.nsPerStepBall << "," << (r.blewUp ? 1 : 0) << "\n";
        }
        out << "\nCSV written to " << *o.csv << "\n";
    }
    if (o.png) {
        if (!writeChart(QString::fromStdString(*o.png), problems, rows)) {
            err << "forcelab-cli sweep: --png: cannot write '" << *o.png << "'\n";
            return 2;
        }
        out << "chart written to " << *o.png << "\n";
    }
    return 0;
}

} // namespace forcelab::cli
