#include "render_bench.h"

#include "trail_recorder.h"
#include "world_painter.h"

#include "lessons/lesson_loader.h"

#include "sim/world/scene.h"
#include "sim/world/world.h"

#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QTextStream>

#include <ctime>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace forcelab {

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

// CPU time of the calling thread, ms: unlike the wall clock it does not
// count time the thread waited for a core that other programs held.
double threadCpuMs()
{
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
#else
    return static_cast<double>(std::clock()) * 1e3 / CLOCKS_PER_SEC;
#endif
}

RenderBenchRow timeFrames(sim::World& world, BallDrawing drawing, const RenderBenchOptions& options)
{
    QImage image(options.size, QImage::Format_ARGB32_Premultiplied);
    WorldPainter painter;
    PaintOptions paint;
    paint.sprites = drawing == BallDrawing::Sprites;
    std::vector<double> ms, cpu;
    const int warmUp = 2;
    for (int frame = 0; frame < warmUp + options.frames; ++frame) {
        // Move every ball a little so each frame draws new positions.
        world.mutableBalls().position.row(0).array() += (frame % 2 ? -0.37 : 0.37);
        QElapsedTimer timer;
        const double cpu0 = threadCpuMs();
        timer.start();
        QPainter p(&image);
        painter.paint(p, QRectF(QPointF(0, 0), QSizeF(options.size)), world, paint, 1.0);
        p.end();
        const double elapsed = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        const double cpuElapsed = threadCpuMs() - cpu0;
        if (frame >= warmUp) {
            ms.push_back(elapsed);
            cpu.push_back(cpuElapsed);
        }
    }
    RenderBenchRow row;
    row.balls = world.balls().size();
    row.meanRadius = world.balls().radius.mean();
    row.drawing = drawing;
    row.medianMs = median(ms);
    row.cpuMedianMs = median(cpu);
    row.minMs = ms.empty() ? 0.0 : *std::min_element(ms.begin(), ms.end());
    row.nsPerBall = row.balls > 0 ? row.medianMs * 1e6 / row.balls : 0.0;
    return row;
}

RenderBenchRow timeLessonWithPaths(const QString& id, bool incremental, const RenderBenchOptions& options)
{
    RenderBenchRow row;
    row.lesson = id;
    row.incremental = incremental;
    const LoadResult loaded = LessonLoader::load(id);
    if (!loaded.ok())
        return row;
    sim::World world(loaded.lesson->scene);
    TrailRecorder trails;
    WorldPainter painter;
    PaintOptions paint;
    paint.overlays = Overlays::fromNames(loaded.lesson->overlays);
    paint.overlays.trails = true;
    paint.trails = &trails;
    paint.incrementalPaths = incremental;
    QImage image(options.lessonSize, QImage::Format_ARGB32_Premultiplied);
    std::vector<double> ms, cpu;
    for (int frame = 0; frame < options.lessonWarmUp + options.frames; ++frame) {
        world.step();
        trails.record(world.balls(), world.time());
        QElapsedTimer timer;
        const double cpu0 = threadCpuMs();
        timer.start();
        QPainter p(&image);
        painter.paint(p, QRectF(QPointF(0, 0), QSizeF(options.lessonSize)), world, paint, 1.0);
        p.end();
        const double elapsed = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        const double cpuElapsed = threadCpuMs() - cpu0;
        if (frame >= options.lessonWarmUp) {
            ms.push_back(elapsed);
            cpu.push_back(cpuElapsed);
        }
    }
    row.balls = world.balls().size();
    row.meanRadius = world.balls().empty() ? 0.0 : world.balls().radius.mean();
    row.medianMs = median(ms);
    row.cpuMedianMs = median(cpu);
    row.minMs = *std::min_element(ms.begin(), ms.end());
    row.maxMs = *std::max_element(ms.begin(), ms.end());
    row.nsPerBall = row.balls > 0 ? row.medianMs * 1e6 / row.balls : 0.0;
    return row;
}

} // namespace

QList<RenderBenchRow> runRenderBench(const RenderBenchOptions& options)
{
    QList<RenderBenchRow> rows;
    for (int n : options.ballCounts) {
        sim::Scene scene;
        scene.settings.box = {1200.0, 800.0};
        // N π r̄² = fill × area (with r uniform in [0.7, 1.3] r̄, E[r²] = 1.03 r̄²).
        const double mean = std::sqrt(options.fill * 1200.0 * 800.0 / (std::max(n, 1) * std::numbers::pi * 1.03));
        scene.spawn.count = n;
        scene.spawn.minRadius = 0.7 * mean;
        scene.spawn.maxRadius = 1.3 * mean;
        scene.spawn.seed = 7;
        sim::World world(scene);
        rows.append(timeFrames(world, BallDrawing::Sprites, options));
        if (options.withBaseline)
            rows.append(timeFrames(world, BallDrawing::Ellipses, options));
    }
    for (const QString& id : options.pathLessons) {
        rows.append(timeLessonWithPaths(id, true, options));
        rows.append(timeLessonWithPaths(id, false, options));
    }
    return rows;
}

QString formatRenderBench(const QList<RenderBenchRow>& rows, const RenderBenchOptions& options)
{
    QString text;
    QTextStream out(&text);
    QList<RenderBenchRow> lessonRows;
    out << "render: " << options.size.width() << "x" << options.size.height() << " px image, box 1200x800 px "
        << options.fill * 100 << "% covered, median of " << options.frames
        << " frames (wall clock; cpu = this thread's CPU time)\n";
    out << QStringLiteral("%1  %2  %3  %4  %5  %6  %7\n")
               .arg(QStringLiteral("balls"), 7)
               .arg(QStringLiteral("r px"), 5)
               .arg(QStringLiteral("drawing"), -15)
               .arg(QStringLiteral("median ms"), 10)
               .arg(QStringLiteral("min ms"), 8)
               .arg(QStringLiteral("cpu ms"), 8)
               .arg(QStringLiteral("ns/ball"), 8);
    for (const RenderBenchRow& r : rows) {
        if (!r.lesson.isEmpty()) {
            lessonRows.append(r);
            continue;
        }
        const QString drawing =
            r.drawing == BallDrawing::Sprites ? QStringLiteral("sprites") : QStringLiteral("drawEllipse");
        out << QStringLiteral("%1  %2  %3  %4  %5  %6  %7\n")
                   .arg(r.balls, 7)
                   .arg(r.meanRadius, 5, 'f', 1)
                   .arg(drawing, -15)
                   .arg(r.medianMs, 10, 'f', 3)
                   .arg(r.minMs, 8, 'f', 3)
                   .arg(r.cpuMedianMs, 8, 'f', 3)
                   .arg(r.nsPerBall, 8, 'f', 1);
    }
    for (const RenderBenchRow& r : lessonRows)
        out << QStringLiteral("lesson %1 with paths %10, %2x%3 px, after %4 frames: median %5 ms, min %6, max %7, "
                              "cpu %8 (%9 balls)\n")
                   .arg(r.lesson)
                   .arg(options.lessonSize.width())
                   .arg(options.lessonSize.height())
                   .arg(options.lessonWarmUp)
                   .arg(r.medianMs, 0, 'f', 3)
                   .arg(r.minMs, 0, 'f', 3)
                   .arg(r.maxMs, 0, 'f', 3)
                   .arg(r.cpuMedianMs, 0, 'f', 3)
                   .arg(r.balls)
                   .arg(r.incremental ? QStringLiteral("appended to a layer") : QStringLiteral("redrawn whole"));
    return text;
}

} // namespace forcelab
