#pragma once
// The collision benchmark behind `forcelab-cli bench`: collision detection
// alone and the whole world step for each detector at several ball counts, a
// per-stage profile, the memory bandwidth the steps reach, and a peer scene
// comparable with other engines. Plain C++: std::chrono and the simulation
// library only. Every figure is a median over several runs in this one
// process, so ratios between rows are taken under the same conditions.

#include <ostream>
#include <string>
#include <vector>

namespace forcelab::sim {

struct CollisionBenchOptions {
    bool quick = false;                                   ///< fewer sizes and runs
    int runs = 7;                                         ///< runs per measurement (the median is reported)
    std::vector<int> sizes{1000, 4000, 10000, 100000};    ///< balls, main table
    std::vector<int> peerSizes{1000, 5000, 10000, 20000}; ///< balls, the peer scene
    int peerSteps = 600;                                  ///< steps of the peer scene
    int bruteLimit = 10000;                               ///< balls, largest count for the all-pairs detector
    bool main = true;                                     ///< the main table
    bool peers = true;                                    ///< the peer table
    bool bandwidth = true;                                ///< the memory bandwidth line
    bool profile = false;                                 ///< per-stage times at the largest size
    double speculative = -1.0;                            ///< 1, the solver's speculative growth; < 0: its default
    int spawnSize = 0;                                    ///< balls of the spawn table (0: no spawn table)
    std::vector<int> spawnSteps{20, 200};                 ///< the spawn table's step counts, from the start
};

/// Runs the benchmark, printing its tables to `out` as it goes; with `csv`,
/// also writes every row there.
void runCollisionBench(const CollisionBenchOptions& options, std::ostream& out, std::ostream* csv);

} // namespace forcelab::sim
