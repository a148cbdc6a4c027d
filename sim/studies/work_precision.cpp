#include "sim/studies/work_precision.h"

#include "sim/integrators/integrator_info.h"

#include "sim/world/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace forcelab::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Steps of dt that make `duration`, or nothing when dt does not divide it
// (every run must end at the same time as the reference to be compared).
std::optional<std::int64_t> wholeSteps(double duration, double dt)
{
    if (!(dt > 0.0) || !(duration > 0.0))
        return std::nullopt;
    const double n = std::round(duration / dt);
    if (!(n >= 1.0 && n <= 0x1p53) || std::abs(n * dt - duration) > 1e-9 * duration) // also refuses inf and NaN
        return std::nullopt;
    return static_cast<std::int64_t>(n);
}

// Runs `scene` with one integrator and step for `steps` steps. The world is
// left at the end for the caller to compare. Returns false when cancelled.
bool runOne(const Scene& scene, IntegratorKind kind, double dt, double tolerance, std::int64_t steps,
            const std::atomic<bool>* cancel, World& world, PrecisionRun& run)
{
    run.integrator = kind;
    run.dt = dt;
    run.tolerance = tolerance;
    Scene s = scene;
    s.settings.time.integrator = kind;
    s.settings.time.dt = dt;
    // dt is the integrator's own step: no splitting into sub-steps.
    s.settings.time.substeps = 1;
    s.settings.time.tolerance = tolerance;
    s.settings.time.perFrame = false;
    if (auto refused = world.reset(s)) {
        run.refused = toString(*refused);
        return true;
    }
    for (std::int64_t k = 0; k < steps && !world.halted(); ++k) {
        if (cancel && cancel->load(std::memory_order_relaxed))
            return false;
        world.step();
    }
    run.steps = world.stepCount();
    run.forceEvaluations = world.totals().forceEvaluations;
    run.wallSeconds = world.totals().seconds;
    run.blewUp = world.halted().has_value();
    return true;
}

} // namespace

double largestSeparation(const World& a, const World& b)
{
    const Matrix2X& x = a.balls().position;
    const Matrix2X& y = b.balls().position;
    if (x.cols() != y.cols())
        return kInf;
    if (x.cols() == 0)
        return 0.0;
    return (x - y).colwise().norm().maxCoeff();
}

WorkPrecisionResult measureWorkPrecision(const Scene& scene, const WorkPrecisionSettings& settings,
                                         const ProgressCallback& progress, const std::atomic<bool>* cancel)
{
    WorkPrecisionResult result;
    if (settings.dts.empty() || settings.integrators.empty()) {
        result.error = "work-precision: no integrators or no time steps to measure";
        return result;
    }
    for (double dt : settings.dts)
        if (!wholeSteps(settings.duration, dt)) {
            result.error = "work-precision: duration " + std::to_string(settings.duration) +
                           " s is not a whole number of steps of dt = " + std::to_string(dt) + " s";
            return result;
        }
    const int total = 1 + static_cast<int>(settings.integrators.size() * settings.dts.size());
    int done = 0;

    // The reference: the 15th-order adaptive integrator at the smallest step,
    // with a tolerance far below any error the others make.
    const double smallest = *std::min_element(settings.dts.begin(), settings.dts.end());
    // A very tight tolerance can run into rounding on a close approach (ias15
    // then asks for ever shorter sub-steps and gives up): the reference then
    // falls back to ias15's default tolerance, still far below the others.
    World reference;
    for (double tolerance : {settings.referenceTolerance, 1e-9}) {
        result.reference = PrecisionRun();
        if (!runOne(scene, IntegratorKind::Ias15, smallest, tolerance, *wholeSteps(settings.duration, smallest),
                    cancel, reference, result.reference)) {
            result.cancelled = true;
            return result;
        }
        if (!result.reference.blewUp)
            break;
    }
    if (!result.reference.refused.empty()) {
        result.error = result.reference.refused;
        return result;
    }
    if (result.reference.blewUp) {
        result.error = "work-precision: the reference run stopped: " + reference.halted().value_or("");
        return result;
    }
    if (progress)
        progress(++done, total);
    const double referenceEnergy = reference.energy().total();
    // Errors of the energy are relative to the reference's; an energy of
    // (nearly) 0 is measured against the kinetic energy's scale instead.
    const double energyScale = std::max(std::abs(referenceEnergy), std::max(reference.energy().kinetic, 1e-300));

    // The runs are independent: with more than one thread each takes the next
    // run not yet started. They only read the scene and the reference.
    struct Job {
        IntegratorKind kind;
        double dt;
    };
    std::vector<Job> jobs;
    for (IntegratorKind kind : settings.integrators)
        for (double dt : settings.dts)
            jobs.push_back({kind, dt});
    std::vector<PrecisionRun> runs(jobs.size());
    std::vector<char> finished(jobs.size(), 0);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stopped{false};
    std::mutex progressMutex;
    auto work = [&] {
        for (std::size_t j = next++; j < jobs.size(); j = next++) {
            World world;
            PrecisionRun& run = runs[j];
            if (!runOne(scene, jobs[j].kind, jobs[j].dt, scene.settings.time.tolerance,
                        *wholeSteps(settings.duration, jobs[j].dt), cancel, world, run)) {
                stopped = true;
                return;
            }
            if (run.refused.empty()) {
                if (run.blewUp) {
                    run.positionError = kInf;
                    run.energyError = kInf;
                } else {
                    run.positionError = largestSeparation(world, reference);
                    run.energyError = std::abs(world.energy().total() - referenceEnergy) / energyScale;
                }
            }
            finished[j] = 1;
            if (progress) {
                const std::lock_guard lock(progressMutex);
                progress(++done, total);
            }
        }
    };
    const int threads = std::clamp(settings.threads, 1, static_cast<int>(std::max<std::size_t>(jobs.size(), 1)));
    std::vector<std::thread> helpers;
    for (int t = 1; t < threads; ++t)
        helpers.emplace_back(work);
    work();
    for (std::thread& t : helpers)
        t.join();
    for (std::size_t j = 0; j < jobs.size(); ++j)
        if (finished[j])
            result.runs.push_back(std::move(runs[j]));
    result.cancelled = stopped;
    return result;
}

double fittedOrder(std::span<const double> dts, std::span<const double> errors)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < std::min(dts.size(), errors.size()); ++i) {
        if (!(errors[i] > 0.0) || !std::isfinite(errors[i]) || !(dts[i] > 0.0))
            continue;
        const double x = std::log(dts[i]), y = std::log(errors[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++n;
    }
    const double d = n * sxx - sx * sx;
    if (n < 2 || !(d > 0.0))
        return std::nan("");
    return (n * sxy - sx * sy) / d;
}

double theoreticalOrder(IntegratorKind integrator)
{
    const IntegratorInfo& info = integratorInfo(integrator);
    return info.adaptive || info.order == 0.0 ? std::nan("") : info.order;
}

ConvergenceResult measureConvergence(const Scene& scene, IntegratorKind integrator, double dt, double duration,
                                     const ProgressCallback& progress, const std::atomic<bool>* cancel)
{
    WorkPrecisionSettings settings;
    settings.duration = duration;
    settings.integrators = {integrator};
    settings.dts = {dt, dt / 2, dt / 4, dt / 8};
    ConvergenceResult c;
    c.study = measureWorkPrecision(scene, settings, progress, cancel);
    std::vector<double> dts, errors;
    for (const PrecisionRun& r : c.study.runs)
        if (r.refused.empty() && !r.blewUp) {
            dts.push_back(r.dt);
            errors.push_back(r.positionError);
        }
    c.order = fittedOrder(dts, errors);
    return c;
}

} // namespace forcelab::sim
