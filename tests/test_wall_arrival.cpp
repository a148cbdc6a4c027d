// When a ball next reaches a wall under its present acceleration, against
// closed forms: a fall from rest takes √(2h/g), a glide d/v, a throw upwards
// that does not reach the ceiling lands on the floor, a ball moving away
// from every wall that is on reaches none, and a ball resting on the floor
// is not "arriving".

#include "sim_check.h"

#include "sim/studies/wall_arrival.h"

#include <cmath>

using namespace forcelab::sim;

namespace {

constexpr double kRel = 1e-12;

BoxSettings box()
{
    return BoxSettings{600.0, 400.0};
}

} // namespace

TEST_CASE("a fall from rest takes the square root of 2h/g")
{
    const auto a = nextWallArrival(box(), WallSettings{}, Vec2(120, 60), Vec2(0, 0), Vec2(0, 980), 20);
    REQUIRE(a);
    CHECK(a->side == WallSide::Bottom);
    const double exact = std::sqrt(2.0 * (400.0 - 20.0 - 60.0) / 980.0);
    CHECK(std::abs(a->seconds - exact) <= kRel * exact);
}

TEST_CASE("a glide reaches the wall after distance over speed; the edge counts unless centre_only")
{
    const auto a = nextWallArrival(box(), WallSettings{}, Vec2(100, 200), Vec2(-30, 0), Vec2(0, 0), 10);
    REQUIRE(a);
    CHECK(a->side == WallSide::Left);
    CHECK(std::abs(a->seconds - 90.0 / 30.0) <= kRel * 3.0);
    WallSettings centre;
    centre.centreOnly = true;
    const auto c = nextWallArrival(box(), centre, Vec2(100, 200), Vec2(-30, 0), Vec2(0, 0), 10);
    REQUIRE(c);
    CHECK(std::abs(c->seconds - 100.0 / 30.0) <= kRel * 4.0);
}

TEST_CASE("a throw that does not reach the ceiling lands on the floor; one that does hits the ceiling")
{
    // From y = 300 upwards at 500 px/s: the top is 500²/(2·980) = 127.6 px higher, at y = 172.4 (below the ceiling).
    const auto low = nextWallArrival(box(), WallSettings{}, Vec2(300, 300), Vec2(0, -500), Vec2(0, 980), 10);
    REQUIRE(low);
    CHECK(low->side == WallSide::Bottom);
    // ½ g t² − 500 t − 90 = 0 (the floor at y = 390 is 90 px below).
    const double t = (500.0 + std::sqrt(500.0 * 500.0 + 2.0 * 980.0 * 90.0)) / 980.0;
    CHECK(std::abs(low->seconds - t) <= kRel * t);
    // At 900 px/s it reaches the ceiling (y = 10) on the way up: ½ g t² − 900 t + 290 = 0, the smaller root.
    const auto high = nextWallArrival(box(), WallSettings{}, Vec2(300, 300), Vec2(0, -900), Vec2(0, 980), 10);
    REQUIRE(high);
    CHECK(high->side == WallSide::Top);
    const double up = (900.0 - std::sqrt(900.0 * 900.0 - 2.0 * 980.0 * 290.0)) / 980.0;
    CHECK(std::abs(high->seconds - up) <= 1e-10 * up);
}

TEST_CASE("no wall: moving away from every wall that is on, or resting on the floor")
{
    WallSettings onlyLeft;
    onlyLeft.right = onlyLeft.top = onlyLeft.bottom = false;
    CHECK(!nextWallArrival(box(), onlyLeft, Vec2(100, 200), Vec2(30, 5), Vec2(0, 0), 10));
    CHECK(!nextWallArrival(box(), WallSettings{}, Vec2(100, 390), Vec2(0, 0), Vec2(0, 980), 10));
}
