#include "custom_force.h"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
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

// muparser's message for a formula, as "column N: what was wrong".
std::optional<Error> checkFormula(const std::string& path, const std::string& formula,
                                  const CustomForceSettings& s)
{
    if (formula.size() > 2000)
        return keyError(path, "the formula is longer than 2000 characters");
    CustomForceSettings one; // fy "0" and no potential: only this formula is compiled
    one.constants = s.constants;
    one.fx = formula;
    try {
        CompiledLaw law(one);
        law.fx.Eval(); // parsing happens here: an unknown name or a missing bracket throws
    } catch (const mu::Parser::exception_type& e) {
        const int column = static_cast<int>(e.GetPos()) + 1;
        std::string message("column ");
        message.append(std::to_string(column)).append(": ");
        if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN || e.GetCode() == mu::ecUNEXPECTED_VAR)
            message.append("unknown name \"")
                .append(e.GetToken())
                .append("\"; use x, y, vx, vy, m, r, q, t, W, H, pi, a function such as sin or sqrt, or add it "
                        "as a constant");
        else
            message.append(e.GetMsg());
        return keyError(path, message);
    }
    return std::nullopt;
}

// A potential must belong to its force, F = −∇U: compared at a few points
// of the box (m = 1, r = 10, q = 1, at rest, t = 0) with central differences.
std::optional<Error> checkPotential(const CustomForceSettings& s, double width, double height)
{
    CompiledLaw law(s);
    for (std::size_t k = 0; k < s.constants.size(); ++k)
        law.constants[k] = s.constants[k].value;
    law.W = width;
    law.H = height;
    law.r = 10.0;
    const double points[][2] = {{0.25, 0.25}, {0.5, 0.4}, {0.75, 0.7}, {0.4, 0.8}};
    for (const auto& p : points) {
        const double x0 = p[0] * width, y0 = p[1] * height;
        const double h = 1e-3 * std::max(1.0, std::max(width, height));
        auto u = [&](double x, double y) {
            law.x = x;
            law.y = y;
            return law.potential.Eval();
        };
        const double gx = -(u(x0 + h, y0) - u(x0 - h, y0)) / (2 * h);
        const double gy = -(u(x0, y0 + h) - u(x0, y0 - h)) / (2 * h);
        law.x = x0;
        law.y = y0;
        const double fx = law.fx.Eval(), fy = law.fy.Eval();
        const double size = std::max({std::abs(fx), std::abs(fy), std::abs(gx), std::abs(gy), 1e-9});
        if (!(std::abs(fx - gx) <= 1e-4 * size && std::abs(fy - gy) <= 1e-4 * size)) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "at (%.0f, %.0f) px −∇U is (%.4g, %.4g) but the force is (%.4g, %.4g): this is not the "
                          "potential of F",
                          x0, y0, gx, gy, fx, fy);
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
        law.x = x(0, i);
        law.y = x(1, i);
        law.vx = v(0, i);
        law.vy = v(1, i);
        law.m = balls.mass[i];
        law.r = balls.radius[i];
        law.q = balls.charge[i];
        const double fx = law.fx.Eval(), fy = law.fy.Eval();
        // a = F / m, unless the formulas already give the acceleration.
        const double scale = s.acceleration ? 1.0 : balls.inverseMass[i];
        a(0, i) += fx * scale;
        a(1, i) += fy * scale;
    }
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
        law.x = x(0, i);
        law.y = x(1, i);
        law.vx = balls.velocity(0, i);
        law.vy = balls.velocity(1, i);
        law.m = balls.mass[i];
        law.r = balls.radius[i];
        law.q = balls.charge[i];
        // With the formulas giving the acceleration, U is per unit mass.
        sum += s.acceleration ? law.m * law.potential.Eval() : law.potential.Eval();
    }
    return sum;
}

} // namespace forcelab::sim
