#include "sim/forces/custom_force.h"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <unordered_map>

namespace forcelab::sim {

namespace {

// One compiled law: a parser per formula, all reading the same variables.
struct CompiledLaw {
    double x = 0, y = 0, vx = 0, vy = 0, m = 1, r = 1, q = 1, t = 0, W = 0, H = 0;
    std::vector<double> constants;
    mu::Parser fx, fy, potential;
    bool hasPotential = false;

    explicit CompiledLaw(const CustomForceSettings& s)
        : constants(s.constants.size(), 0.0)
    {
        for (mu::Parser* p : {&fx, &fy, &potential})
            define(*p, s);
        fx.SetExpr(s.fx);
        fy.SetExpr(s.fy);
        hasPotential = !s.potential.empty();
        potential.SetExpr(hasPotential ? s.potential : std::string("0"));
    }

    /// The formulas' variables for ball i at position x and velocity v.
    void setBall(const BallState& balls, const Matrix2X& xs, const Matrix2X& vs, int i)
    {
        x = xs(0, i);
        y = xs(1, i);
        vx = vs(0, i);
        vy = vs(1, i);
        m = balls.mass[i];
        r = balls.radius[i];
        q = balls.charge[i];
    }

    void define(mu::Parser& p, const CustomForceSettings& s)
    {
        p.DefineVar("x", &x);
        p.DefineVar("y", &y);
        p.DefineVar("vx", &vx);
        p.DefineVar("vy", &vy);
        p.DefineVar("m", &m);
        p.DefineVar("r", &r);
        p.DefineVar("q", &q);
        p.DefineVar("t", &t);
        p.DefineVar("W", &W);
        p.DefineVar("H", &H);
        p.DefineConst("pi", std::numbers::pi);
        for (std::size_t k = 0; k < s.constants.size(); ++k)
            p.DefineVar(s.constants[k].name, &constants[k]);
    }
};

// The formulas and the constants' names: what the compiled law depends on.
std::string lawKey(const CustomForceSettings& s)
{
    std::string key;
    for (const std::string* part : {&s.fx, &s.fy, &s.potential}) {
        key.append(*part);
        key.push_back('\n');
    }
    for (const CustomConstant& c : s.constants) {
        key.append(c.name);
        key.push_back('\n');
    }
    return key;
}

// The compiled law for these settings, compiled on first use in this thread
// (muparser's parsers are not to be shared between threads).
CompiledLaw& lawFor(const CustomForceSettings& s)
{
    thread_local std::unordered_map<std::string, std::unique_ptr<CompiledLaw>> cache;
    const std::string key = lawKey(s);
    auto it = cache.find(key);
    if (it == cache.end()) {
        if (cache.size() > 64)
            cache.clear(); // many edits: keep the memory bounded
        it = cache.emplace(key, std::make_unique<CompiledLaw>(s)).first;
    }
    CompiledLaw& law = *it->second;
    for (std::size_t k = 0; k < s.constants.size(); ++k)
        law.constants[k] = s.constants[k].value;
    return law;
}

bool isName(const std::string& name)
{
    if (name.empty() || name.size() > 32 || !std::isalpha(static_cast<unsigned char>(name[0])))
        return false;
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
            return false;
    return true;
}

// Long text in a message is cut to `radius` characters either side of
// `column` (1-based; 0: from the start), with "…" where something was left
// out: a 10,000-character formula must not make a 10 KB message.
std::string excerpt(const std::string& text, std::size_t column, std::size_t radius = 40)
{
    if (text.size() <= 2 * radius + 1)
        return text;
    const std::size_t at = column > 0 ? std::min(column - 1, text.size()) : 0;
    std::size_t from = at > radius ? at - radius : 0;
    std::size_t to = std::min(text.size(), from + 2 * radius + 1);
    from = to - std::min(to, 2 * radius + 1); // a window near the end is still full width
    // Cut between UTF-8 characters, not inside one.
    const auto continuation = [&](std::size_t i) { return i < text.size() && (text[i] & 0xC0) == 0x80; };
    while (from > 0 && continuation(from))
        --from;
    while (continuation(to))
        ++to;
    return (from > 0 ? "…" : "") + text.substr(from, to - from) + (to < text.size() ? "…" : "");
}

// muparser's message for a formula, as "column N: what was wrong". A
// formula too long to read whole in a message is shown around the column.
std::optional<Error> checkFormula(const std::string& path, const std::string& formula,
                                  const CustomForceSettings& s)
{
    if (formula.size() > 2000)
        return keyError(path, "the formula is " + std::to_string(formula.size()) +
                                  " characters long, more than the limit of 2000");
    CustomForceSettings one; // fy "0" and no potential: only this formula is compiled
    one.constants = s.constants;
    one.fx = formula;
    try {
        CompiledLaw law(one);
        law.fx.Eval(); // parsing happens here: an unknown name or a missing bracket throws
        // muparser reads "1, 2" as two formulas and gives the last: a law is
        // one formula, so a comma outside a function's brackets is an error.
        if (law.fx.GetNumResults() != 1) {
            std::size_t column = 0;
            int depth = 0;
            for (std::size_t i = 0; i < formula.size() && column == 0; ++i) {
                depth += formula[i] == '(' ? 1 : formula[i] == ')' ? -1 : 0;
                if (formula[i] == ',' && depth == 0)
                    column = i + 1;
            }
            std::string message = "column " + std::to_string(column) +
                                  ": a comma outside brackets; a law is one formula (commas separate a "
                                  "function's arguments, as in min(a, b))";
            if (formula.size() > 80)
                message.append(" (at \"").append(excerpt(formula, column)).append("\")");
            return keyError(path, message);
        }
    } catch (const mu::Parser::exception_type& e) {
        const std::size_t column = static_cast<std::size_t>(e.GetPos()) + 1;
        const std::string token = e.GetToken();
        const std::string shortToken = excerpt(token, 0, 20);
        std::string message("column ");
        message.append(std::to_string(column)).append(": ");
        if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN || e.GetCode() == mu::ecUNEXPECTED_VAR) {
            message.append("unknown name \"")
                .append(shortToken)
                .append("\"; use x, y, vx, vy, m, r, q, t, W, H, pi, a function such as sin or sqrt, or add it "
                        "as a constant");
        } else {
            std::string what = e.GetMsg(); // it may quote the token: quote it cut
            if (token.size() > shortToken.size())
                for (std::size_t at = what.find(token); at != std::string::npos; at = what.find(token, at))
                    what.replace(at, token.size(), shortToken);
            message.append(what);
        }
        if (formula.size() > 80)
            message.append(" (at \"").append(excerpt(formula, column)).append("\")");
        return keyError(path, message);
    }
    return std::nullopt;
}

// One derivative by Ridders' method (Numerical Recipes, §5.7): central
// differences at steps shrinking by 1.4, extrapolated to step 0 in a Neville
// tableau. The tableau's neighbours estimate the answer's own error,
// truncation and rounding both; it stops when a higher order stops helping
// (rounding has taken over).
struct Derivative {
    double value = 0.0;
    double error = std::numeric_limits<double>::infinity();
};

template <class Function>
Derivative ridders(Function&& u, double x0, double h0)
{
    constexpr int kRounds = 12;
    constexpr double kShrink = 1.4, kShrink2 = kShrink * kShrink;
    // The step actually taken, (x0 + h) − (x0 − h), is what x0 ± h round to:
    // dividing by it, not by 2h, keeps the position's rounding out.
    const auto central = [&](double h) {
        const double xp = x0 + h, xm = x0 - h;
        return (u(xp) - u(xm)) / (xp - xm);
    };
    double table[kRounds][kRounds];
    Derivative best;
    double h = h0;
    table[0][0] = central(h);
    for (int i = 1; i < kRounds; ++i) {
        h /= kShrink;
        table[0][i] = central(h);
        double factor = kShrink2;
        for (int j = 1; j <= i; ++j) {
            table[j][i] = (table[j - 1][i] * factor - table[j - 1][i - 1]) / (factor - 1.0);
            factor *= kShrink2;
            const double error = std::max(std::abs(table[j][i] - table[j - 1][i]),
                                          std::abs(table[j][i] - table[j - 1][i - 1]));
            if (error <= best.error)
                best = Derivative{table[j][i], error};
        }
        if (std::abs(table[i][i] - table[i - 1][i - 1]) >= 2.0 * best.error)
            break;
    }
    return best;
}

// ∂U/∂x (or ∂U/∂y) at a point, with its error. The first step is scaled to
// the position, 2⁻⁸ |x0| (a fixed step in px is too coarse near a centre of
// force: 0.6 px 40 px from an inverse-square centre is off by 2e-4, and too
// fine far out); when its estimate is poor (a centre closer than the step),
// Ridders starts again with steps 64 and 4096 times shorter, and the best
// answer is kept. Rounding of U itself, a few units in the last place of the
// largest |U| met, divided by the shortest step, is added to the error:
// Ridders' estimate may miss it by luck.
template <class Function>
Derivative partial(Function&& u, double x0)
{
    constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
    double uLargest = 0.0;
    const auto tracked = [&](double x) {
        const double value = u(x);
        uLargest = std::max(uLargest, std::abs(value));
        return value;
    };
    const double scale = std::max(1.0, std::abs(x0));
    Derivative best;
    double shortest = 0.0; // the shortest step of the attempt that gave `best`
    double h0 = std::ldexp(scale, -8);
    for (int attempt = 0; attempt < 3; ++attempt) {
        const Derivative d = ridders(tracked, x0, h0);
        if (d.error < best.error) {
            best = d;
            shortest = h0 / std::pow(1.4, 11);
        }
        if (best.error <= 1e-10 * std::abs(best.value))
            break;
        h0 /= 64.0;
    }
    if (shortest > 0.0) // else no attempt gave an estimate: the error stays unbounded
        best.error += 16.0 * kEpsilon * uLargest / shortest;
    return best;
}

// A potential must belong to its force, F = −∇U: compared at a few points
// of the box (m = 1, r = 10, q = 1, at rest, t = 0). The tolerance is the
// derivative's own estimated error (a few times it) and 1e-8 of the force,
// for the rounding of the force's formula; a law that is really another's
// potential is off by far more. A point where U or F is not a finite number
// (a centre of force on it) proves nothing and is passed over.
std::optional<Error> checkPotential(const CustomForceSettings& s, double width, double height)
{
    CompiledLaw law(s);
    for (std::size_t k = 0; k < s.constants.size(); ++k)
        law.constants[k] = s.constants[k].value;
    law.W = width;
    law.H = height;
    law.r = 10.0;
    // U must be a number wherever the force is one: a U that is not (the
    // square root of a negative number, a logarithm of one) made the energy
    // "nan" in every readout once a ball went there. Checked on a 9 × 9 grid
    // over the box, edges included.
    constexpr int kGrid = 9;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            law.x = width * i / (kGrid - 1);
            law.y = height * j / (kGrid - 1);
            const double fx = law.fx.Eval(), fy = law.fy.Eval();
            if (std::isfinite(fx) && std::isfinite(fy) && !std::isfinite(law.potential.Eval())) {
                char text[200];
                std::snprintf(text, sizeof text,
                              "U is not a number at (%.0f, %.0f) px, where the force is (%.6g, %.6g): a potential "
                              "must have a value wherever its force does",
                              law.x, law.y, fx + 0.0, fy + 0.0);
                return keyError("models.custom.potential", text);
            }
        }
    const double points[][2] = {{0.25, 0.25}, {0.5, 0.4}, {0.75, 0.7}, {0.4, 0.8}};
    for (const auto& p : points) {
        const double x0 = p[0] * width, y0 = p[1] * height;
        const auto u = [&](double x, double y) {
            law.x = x;
            law.y = y;
            return law.potential.Eval();
        };
        const double u0 = u(x0, y0);
        law.x = x0;
        law.y = y0;
        const double fx = law.fx.Eval(), fy = law.fy.Eval();
        if (!std::isfinite(u0) || !std::isfinite(fx) || !std::isfinite(fy))
            continue;
        const Derivative dx = partial([&](double x) { return u(x, y0); }, x0);
        const Derivative dy = partial([&](double y) { return u(x0, y); }, y0);
        const double gx = -dx.value, gy = -dy.value;
        const double size = std::max({std::abs(fx), std::abs(fy), std::abs(gx), std::abs(gy)});
        const auto agrees = [&](double f, double g, double error) {
            return std::abs(f - g) <= 1e-8 * size + 4.0 * error;
        };
        if (!(agrees(fx, gx, dx.error) && agrees(fy, gy, dy.error))) {
            // + 0.0 writes −0 as 0.
            char text[240];
            std::snprintf(text, sizeof text,
                          "at (%.0f, %.0f) px −∇U is (%.6g, %.6g) but the force is (%.6g, %.6g): this is not the "
                          "potential of F",
                          x0, y0, gx + 0.0, gy + 0.0, fx + 0.0, fy + 0.0);
            return keyError("models.custom.potential", text);
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<Error> checkCustomForce(const CustomForceSettings& s, double width, double height)
{
    std::vector<std::string> seen;
    for (const CustomConstant& c : s.constants) {
        std::string path("models.custom.constants.");
        path.append(c.name);
        std::string quoted("\"");
        quoted.append(c.name).append("\"");
        if (!isName(c.name))
            return keyError("models.custom.constants",
                            quoted.append(" is not a name: letters, digits and _, starting with a letter"));
        for (const char* v : kCustomVariables)
            if (c.name == v)
                return keyError(path, quoted.append(" is already a variable of the law; choose another name"));
        if (c.name == "pi")
            return keyError(path, "\"pi\" is already 3.14159…; choose another name");
        for (const std::string& other : seen)
            if (other == c.name)
                return keyError(path, quoted.append(" is defined twice"));
        seen.push_back(c.name);
        if (!std::isfinite(c.value) || !std::isfinite(c.min) || !std::isfinite(c.max))
            return keyError(path, "the value and the slider range must be finite numbers");
        if (!(c.min < c.max))
            return keyError(path, "the slider range is empty: give min < max");
        if (c.value < c.min || c.value > c.max)
            return keyError(path, "the value is outside its slider range; widen the range or change the value");
    }
    if (auto e = checkFormula("models.custom.fx", s.fx, s))
        return e;
    if (auto e = checkFormula("models.custom.fy", s.fy, s))
        return e;
    if (!s.potential.empty()) {
        if (auto e = checkFormula("models.custom.potential", s.potential, s))
            return e;
        try {
            if (auto e = checkPotential(s, width, height))
                return e;
        } catch (const mu::Parser::exception_type& e) {
            return keyError("models.custom.potential", e.GetMsg());
        }
    }
    return std::nullopt;
}

void addCustomAcceleration(const WorldSettings& settings, const BallState& balls, const Matrix2X& x,
                           const Matrix2X& v, double t, Matrix2X& a)
{
    const CustomForceSettings& s = settings.custom;
    CompiledLaw& law = lawFor(s);
    law.t = t;
    law.W = settings.box.width;
    law.H = settings.box.height;
    const int n = balls.size();
    for (int i = 0; i < n; ++i) {
        law.setBall(balls, x, v, i);
        const double fx = law.fx.Eval(), fy = law.fy.Eval();
        // a = F / m, unless the formulas already give the acceleration.
        const double scale = s.acceleration ? 1.0 : balls.inverseMass[i];
        a(0, i) += fx * scale;
        a(1, i) += fy * scale;
    }
}

std::string describeCustomLaw(const CustomForceSettings& c)
{
    const auto cut = [](const std::string& formula) {
        constexpr std::size_t kShown = 60;
        if (formula.size() <= kShown + 20)
            return formula;
        std::size_t end = kShown;
        while (end > 0 && (static_cast<unsigned char>(formula[end]) & 0xC0) == 0x80) // not inside a UTF-8 character
            --end;
        return formula.substr(0, end) + "… (" + std::to_string(formula.size()) + " characters)";
    };
    return "the custom force (F_x = " + cut(c.fx) + ", F_y = " + cut(c.fy) + ")";
}

int firstBallWithoutPotential(const WorldSettings& settings, const BallState& balls, const Matrix2X& x)
{
    const CustomForceSettings& s = settings.custom;
    if (!s.enabled || s.potential.empty())
        return -1;
    CompiledLaw& law = lawFor(s);
    law.W = settings.box.width;
    law.H = settings.box.height;
    for (int i = 0; i < balls.size(); ++i) {
        law.setBall(balls, x, balls.velocity, i);
        if (!std::isfinite(law.potential.Eval()))
            return i;
    }
    return -1;
}

double customPotential(const WorldSettings& settings, const BallState& balls, const Matrix2X& x)
{
    const CustomForceSettings& s = settings.custom;
    if (s.potential.empty())
        return 0.0;
    CompiledLaw& law = lawFor(s);
    law.W = settings.box.width;
    law.H = settings.box.height;
    double sum = 0.0;
    for (int i = 0; i < balls.size(); ++i) {
        law.setBall(balls, x, balls.velocity, i);
        // With the formulas giving the acceleration, U is per unit mass.
        sum += s.acceleration ? law.m * law.potential.Eval() : law.potential.Eval();
    }
    return sum;
}

} // namespace forcelab::sim
