#pragma once
// The subcommands of forcelab-cli. Each takes the arguments after its name,
// writes results to `out` and one-line errors to `err`, and returns the exit
// code (0 success, 2 bad input, 3 the simulation stopped because it blew up).

#include <ostream>
#include <string>
#include <vector>

namespace forcelab::cli {

/// forcelab-cli soak [--steps N] [--balls N]: a long run that checks for drift, NaN and memory growth.
int soakCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// forcelab-cli run LESSON [options]: runs a lesson headless.
int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// forcelab-cli validate FILE...: checks lesson files, prints "FILE: ok" or
/// every problem; 0 when all are valid, 2 otherwise.
int validateCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// forcelab-cli sweep [options]: work-precision study of the integrators on
/// reference problems with closed-form answers (table, CSV, PNG chart).
int sweepCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// forcelab-cli render LESSON --time T --out FILE.png [--size WxH]: draws the
/// lesson at simulated time T with the canvas's painter. Needs a QGuiApplication.
int renderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// forcelab-cli check [LESSON...]: runs every claim of the lessons (all
/// built-in ones by default); 0 when all hold, 1 when one does not, 2 when a
/// lesson does not load.
int checkCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// forcelab-cli handbook --out FILE.html: the teacher's handbook of the built-in lessons.
int handbookCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace forcelab::cli

/// forcelab-cli bench [options]: collision and step benchmarks.
int benchCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
