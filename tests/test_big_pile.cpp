// The peer scene at 20,000 balls (r = 5 px, 30% of a 2,288 px box,
// e = 0.9, 60 Hz, one sub-step, issue #18 item 1). It takes about 20 s in a
// release build and ten times that under the sanitizers, so CMake leaves it
// out of the sanitizer build; test_collision_world runs the same solver on
// the 5,000-ball pile there.

#include "sim/studies/peer_scene.h"
#include "sim/world/world.h"

#include "sim_check.h"

#include <cmath>

using forcelab::test::Text;

using namespace forcelab::sim;

// After 10 s the pile stands: deepest overlap below 0.3 r (measured
// 0.116 r), mean overlap below 0.05 r (0.0081 r), mean height within 2% of
// the 4-sub-step pile's 386.9 px (381.6 px; `forcelab-cli pile --balls 20000
// --substeps 4` prints it), and the balls of the pile slower than 1 px/s rms
// (0.32 px/s). The rms over all balls is 2.48 px/s, and that is one ball: the
// top rows fall up to 1,500 px onto the pile and bounce back with e = 0.9
// (at 1,550 px/s for one of them), and a ball that keeps 0.8 of its speed
// at each bounce on the pile needs about 2·1550 / (980·0.2) ≈ 16 s of
// bounces to come to rest. So at 10 s a few balls may still be in the air;
// more than one in a thousand would mean the pile throws balls off itself.
TEST_CASE("TestBigPile::peerPileStandsAt20000Balls")
{
    World w(peerScene(20000));
    for (int step = 0; step < 600; ++step)
        w.step();
    const PileMeasures m = measurePile(w);
    forcelab::test::report("peer pile, 20,000 balls, 10 s: deepest overlap %.3f r, mean %.4f r, rms speed %.2f px/s "
                           "(of the pile %.2f px/s, %d balls in flight), mean height %.1f px",
                           m.deepestOverlap, m.meanOverlap, m.rmsSpeed, m.pileRmsSpeed, m.inFlight, m.meanHeight);
    VERIFY2(m.deepestOverlap < 0.3, Text(Text::number(m.deepestOverlap)).c_str());
    VERIFY2(m.meanOverlap < 0.05, Text(Text::number(m.meanOverlap)).c_str());
    VERIFY2(std::abs(m.meanHeight - 386.9) <= 0.02 * 386.9, Text(Text::number(m.meanHeight)).c_str());
    VERIFY2(m.pileRmsSpeed < 1.0, Text(Text::number(m.pileRmsSpeed)).c_str());
    VERIFY2(m.inFlight <= 20, Text(Text::number(m.inFlight)).c_str());
}
