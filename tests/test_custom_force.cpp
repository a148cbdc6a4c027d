// A student's force law written as formulas: the custom spring runs like the
// built-in spring with every integrator (1e-12), a custom law equal to
// gravity like the gravity model, a potential is checked against its force,
// malformed formulas are refused with the column and keep the last law, and
// a law that blows up (a division by zero) stops the world with a message
// that names the custom force.

// GCC 12 warns falsely about std::string assignments of literals at -O3
// (its bug 105329); the formulas below are such assignments.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include "sim_check.h"
#include "sim_test_util.h"

#include "sim/forces/custom_force.h"
#include "sim/world/world.h"

#include <cmath>
#include <string>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;

namespace {

Scene twoBalls(IntegratorKind integrator)
{
    Scene s;
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.time.integrator = integrator;
    s.settings.time.dt = 1.0 / 120.0;
    s.balls = {ballAt(400.0, 200.0, 0.0, 150.0, 10.0), ballAt(250.0, 120.0, -40.0, 0.0, 20.0)};
    return s;
}

double largestDifference(const World& a, const World& b)
{
    return std::max((a.balls().position - b.balls().position).cwiseAbs().maxCoeff(),
                    (a.balls().velocity - b.balls().velocity).cwiseAbs().maxCoeff());
}

} // namespace

TEST_CASE("a custom spring matches the built-in spring with every integrator")
{
    for (IntegratorKind kind : {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet,
                                IntegratorKind::Rk4, IntegratorKind::Yoshida4, IntegratorKind::Rk45,
                                IntegratorKind::Ias15}) {
        CAPTURE(static_cast<int>(kind));
        Scene builtIn = twoBalls(kind);
        builtIn.settings.spring.enabled = true;
        builtIn.settings.spring.k = 4.0;
        builtIn.settings.spring.anchor = Vec2(300.0, 200.0);
        Scene custom = twoBalls(kind);
        custom.settings.custom.enabled = true;
        custom.settings.custom.acceleration = true;
        custom.settings.custom.fx = "-k*(x - 300)";
        custom.settings.custom.fy = "-k*(y - 200)";
        custom.settings.custom.constants = {{"k", 4.0, 0.0, 20.0}};
        World a(builtIn), b(custom);
        for (int k = 0; k < 600; ++k) {
            a.step();
            b.step();
        }
        CHECK(largestDifference(a, b) <= 1e-12 * 400.0);
    }
}

TEST_CASE("a custom force m g down is the gravity model")
{
    Scene gravity = twoBalls(IntegratorKind::Rk4);
    gravity.settings.gravity.enabled = true;
    gravity.settings.gravity.g = Vec2(0.0, 980.0);
    Scene custom = twoBalls(IntegratorKind::Rk4);
    custom.settings.custom.enabled = true;
    custom.settings.custom.fx = "0";
    custom.settings.custom.fy = "m*g";
    custom.settings.custom.potential = "-m*g*y";
    custom.settings.custom.constants = {{"g", 980.0, 0.0, 2000.0}};
    World a(gravity), b(custom);
    for (int k = 0; k < 300; ++k) {
        a.step();
        b.step();
    }
    // F = m g, then a = F / m: one rounding per step apart at most.
    CHECK(largestDifference(a, b) <= 1e-9);
    // Its potential is counted: the total energy is the same as gravity's.
    CHECK(std::abs(a.energy().total() - b.energy().total()) <= 1e-9 * std::abs(a.energy().total()));
}

TEST_CASE("malformed formulas are refused with the column, and the world keeps its law")
{
    Scene s = twoBalls(IntegratorKind::Rk4);
    s.settings.custom.enabled = true;
    s.settings.custom.fx = "-k*x";
    s.settings.custom.constants = {{"k", 1.0, 0.0, 10.0}};
    World world(s);
    struct Bad {
        const char* field;
        const char* formula;
        const char* key;
        const char* expect;
    };
    for (const Bad& bad : {Bad{"fx", "-kk*x", "models.custom.fx", "column 2: unknown name \"kk\""},
                           Bad{"fy", "2*(y + 1", "models.custom.fy", "column"},
                           Bad{"fx", "3 +* x", "models.custom.fx", "column"},
                           Bad{"fx", "sin(x", "models.custom.fx", "column"},
                           // muparser reads "1, 2" as two formulas and gave the last one
                           Bad{"fx", "1, 2", "models.custom.fx", "column 2: a comma outside brackets"},
                           Bad{"fy", "min(x, 1), -k*y", "models.custom.fy", "column 10: a comma outside brackets"}}) {
        CAPTURE(bad.formula);
        WorldSettings edit = world.settings();
        (std::string(bad.field) == "fx" ? edit.custom.fx : edit.custom.fy) = bad.formula;
        const auto error = world.setSettings(edit);
        REQUIRE(error.has_value());
        CHECK(error->keyPath == bad.key);
        CHECK(error->message.find(bad.expect) != std::string::npos);
        CHECK(world.settings().custom.fx == "-k*x"); // the last good law stays
    }
    WorldSettings edit = world.settings();
    edit.custom.constants.push_back({"x", 1.0, 0.0, 2.0});
    const auto clash = world.setSettings(edit);
    REQUIRE(clash.has_value());
    CHECK(clash->keyPath == "models.custom.constants.x");
}

TEST_CASE("a potential that does not belong to its force is refused")
{
    CustomForceSettings c;
    c.enabled = true;
    c.fx = "0";
    c.fy = "m*980";
    c.potential = "m*980*y"; // the sign is wrong: F = −∇U needs −m g y
    const auto error = checkCustomForce(c, 600.0, 400.0);
    REQUIRE(error.has_value());
    CHECK(error->keyPath == "models.custom.potential");
    c.potential = "-m*980*y";
    CHECK(!checkCustomForce(c, 600.0, 400.0).has_value());
}

TEST_CASE("a law that divides by zero stops the world and names the custom force")
{
    Scene s = twoBalls(IntegratorKind::SemiImplicitEuler);
    s.settings.custom.enabled = true;
    s.settings.custom.fx = "1/(x - 400)"; // ball 0 starts at x = 400
    World world(s);
    world.step();
    REQUIRE(world.halted().has_value());
    CHECK(world.halted()->find("custom force") != std::string::npos);
    CHECK(world.balls().position.allFinite());

    s.settings.custom.fx = "sqrt(-1)"; // not a number
    World nan(s);
    nan.step();
    REQUIRE(nan.halted().has_value());
    CHECK(nan.halted()->find("custom force") != std::string::npos);
}

namespace {

// An inverse-square attraction of strength S to (cx, cy) with its potential
// U = −S m / r: F = −∇U exactly.
CustomForceSettings inverseSquare(double cx, double cy, double strength, const char* power = "")
{
    CustomForceSettings c;
    c.enabled = true;
    const std::string dx = "(x - " + std::to_string(cx) + ")", dy = "(y - " + std::to_string(cy) + ")";
    const std::string r2 = "(" + dx + "^2 + " + dy + "^2)";
    c.fx = "-S*m*" + dx + "/" + r2 + "^1.5";
    c.fy = "-S*m*" + dy + "/" + r2 + "^1.5";
    c.potential = std::string("-S*m") + power + "/sqrt" + r2;
    c.constants = {{"S", strength, 0.0, 2.0 * strength}};
    return c;
}

} // namespace

// Issue #31 item 8. U = −S m / r with S = 1e6 and the centre at (300, 200)
// is the potential of its inverse-square force, but 40 px from the centre
// (the check point (300, 160)) a central difference of 0.6 px is off by
// h²/r² = 2.25e-4, more than the 1e-4 allowed: "−∇U is (−0, 625.1) but the
// force is (−0, 625)". Ridders' extrapolation from a step scaled to the
// position, with its own error estimate, accepts it, also with the centre
// 1 px and 0.01 px from a check point and in a box 100 times larger.
TEST_CASE("a correct inverse-square potential is accepted")
{
    struct Case {
        double cx, cy, width, height;
    };
    for (const Case& k : {Case{300, 200, 600, 400}, Case{300, 161, 600, 400}, Case{300.01, 160, 600, 400},
                          Case{30000, 20000, 60000, 40000}, Case{3, 2, 6, 4}}) {
        CAPTURE(k.cx);
        CAPTURE(k.width);
        const auto error = checkCustomForce(inverseSquare(k.cx, k.cy, 1e6), k.width, k.height);
        CHECK_MESSAGE(!error.has_value(), (error ? error->message : std::string()));
    }
}

// ... and potentials that belong to another force are still refused, even
// where they differ little: the wrong power of r, a strength 0.1% off, the
// wrong sign, the centre 0.1 px away.
TEST_CASE("a potential of another force is still refused")
{
    CustomForceSettings wrongPower = inverseSquare(300, 200, 1e6);
    wrongPower.potential = "-S*m/((x - 300)^2 + (y - 200)^2)";
    CustomForceSettings offByAThousandth = inverseSquare(300, 200, 1e6);
    offByAThousandth.potential = "-1.001*S*m/sqrt((x - 300)^2 + (y - 200)^2)";
    CustomForceSettings wrongSign = inverseSquare(300, 200, 1e6);
    wrongSign.potential = "S*m/sqrt((x - 300)^2 + (y - 200)^2)";
    CustomForceSettings movedCentre = inverseSquare(300, 200, 1e6);
    movedCentre.potential = "-S*m/sqrt((x - 300.1)^2 + (y - 200)^2)";
    for (const CustomForceSettings& c : {wrongPower, offByAThousandth, wrongSign, movedCentre}) {
        CAPTURE(c.potential);
        const auto error = checkCustomForce(c, 600.0, 400.0);
        REQUIRE(error.has_value());
        CHECK(error->keyPath == "models.custom.potential");
        CHECK(error->message.find("this is not the potential of F") != std::string::npos);
    }
}

// Issue #31 item 11. A refused formula is shown around its error, not whole:
// a 1,900-character formula with an unknown name 1,000 characters long
// made a message of over 1,000 characters. The name and the formula are now
// cut to 40 characters either side of the column, with "…".
TEST_CASE("a long refused formula is shown around its error")
{
    CustomForceSettings c;
    c.enabled = true;
    std::string formula;
    for (int k = 0; k < 100; ++k)
        formula += "x + ";
    const std::size_t column = formula.size() + 1;
    formula += std::string(1000, 'z') + " + " + std::string(500, '1');
    c.fx = formula;
    const auto error = checkCustomForce(c, 600.0, 400.0);
    REQUIRE(error.has_value());
    forcelab::test::report("%zu characters: %s", error->message.size(), error->message.c_str());
    CHECK(error->message.rfind("column " + std::to_string(column) + ": unknown name", 0) == 0);
    CHECK(error->message.size() < 400);
    CHECK(error->message.find("x + x + zzz") != std::string::npos); // the part around the column
    // Past the limit the message says how long it is, in a line.
    c.fx = std::string(10000, 'x');
    const auto tooLong = checkCustomForce(c, 600.0, 400.0);
    REQUIRE(tooLong.has_value());
    CHECK(tooLong->message == "the formula is 10000 characters long, more than the limit of 2000");
}

// Issue #33. A potential that is not a number over part of the box, where
// the force is one, is refused: before, U = ½ k m (x − 300)² + 0·√(x − 300)
// was accepted and the energy read "nan" in every readout. A law singular at
// a point, where U and F both fail, is still accepted (above).
TEST_CASE("a potential that is not a number where the force is one is refused")
{
    CustomForceSettings c;
    c.enabled = true;
    c.fx = "-k*m*(x - 300)";
    c.fy = "0";
    c.constants = {{"k", 4.0, 0.0, 10.0}};
    c.potential = "0.5*k*m*(x - 300)^2";
    CHECK(!checkCustomForce(c, 600, 400));
    c.potential = "0.5*k*m*(x - 300)^2 + 0*sqrt(x - 300)";
    const auto error = checkCustomForce(c, 600, 400);
    REQUIRE(error.has_value());
    CHECK(error->keyPath == "models.custom.potential");
    CHECK(error->message.find("U is not a number at (0, 0) px") != std::string::npos);
}

// U = 0·√((x − 291)(x − 293)) is 0 everywhere but between x = 291 and 293 px,
// where it is not a number: the load-time grid does not sample there, so it
// is accepted. A ball crossing at 100 px/s (1.67 px per step) ends a step
// in that strip; the world stops one step before, names the ball and the
// place, and the energy it reported was never NaN. Before, the energy read
// null at step 55 and the run went on.
TEST_CASE("a potential undefined between the sampled points stops the world where a ball meets it")
{
    Scene s;
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.time.dt = 1.0 / 60.0;
    s.settings.custom.enabled = true;
    s.settings.custom.fx = "0";
    s.settings.custom.fy = "0";
    s.settings.custom.potential = "0*sqrt((x-291)*(x-293))";
    s.balls = {ballAt(200.0, 200.0, 100.0, 0.0, 10.0)};
    REQUIRE(!checkCustomForce(s.settings.custom, 600, 400));
    World w(s);
    for (int k = 0; k < 120 && !w.halted(); ++k) {
        w.step();
        CHECK(std::isfinite(w.energy().total()));
    }
    REQUIRE(w.halted().has_value());
    CHECK(w.halted()->find("is not a number: ball 0 at (291.7, 200) px") != std::string::npos);
    CHECK(w.balls().position(0, 0) < 291.0); // the step into the strip is undone
}
