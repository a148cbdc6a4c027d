#include "ui/docks/trajectory_export.h"

#include "ui/canvas/simulation_controller.h"

#include <QSaveFile>
#include <QTextStream>

#include <limits>

namespace forcelab {

TrajectoryExport::TrajectoryExport(QObject* parent)
    : QObject(parent)
{
}

TrajectoryExport::TrajectoryExport(SimulationController* controller, QObject* parent)
    : QObject(parent)
{
    connect(controller, &SimulationController::stepped, this, [this, controller] {
        if (m_recording)
            record(controller->world());
    });
    connect(controller, &SimulationController::sceneChanged, this, &TrajectoryExport::stop);
}

void TrajectoryExport::start(const sim::World& world, int ball)
{
    m_rows.clear();
    m_full = false;
    m_ball = ball >= 0 && ball < world.balls().size() ? ball : -1;
    const bool was = m_recording;
    m_recording = true;
    m_lastTime = -std::numeric_limits<double>::infinity(); // the current state is the first record
    record(world);
    if (!was)
        emit recordingChanged(true);
}

void TrajectoryExport::stop()
{
    if (!m_recording)
        return;
    m_recording = false;
    emit recordingChanged(false);
}

void TrajectoryExport::clear()
{
    m_rows.clear();
    m_full = false;
}

void TrajectoryExport::record(const sim::World& world)
{
    if (!m_recording || !(world.time() > m_lastTime))
        return;
    const sim::BallState& balls = world.balls();
    if (m_ball >= balls.size()) { // the ball is gone (a new scene): nothing to follow
        stop();
        return;
    }
    const int first = m_ball >= 0 ? m_ball : 0;
    const int last = m_ball >= 0 ? m_ball + 1 : balls.size();
    if (m_rows.size() + static_cast<std::size_t>(last - first) > kMaxRows) {
        m_full = true;
        stop();
        return;
    }
    m_lastTime = world.time();
    for (int i = first; i < last; ++i)
        m_rows.push_back({world.time(), i, balls.position(0, i), balls.position(1, i), balls.velocity(0, i),
                          balls.velocity(1, i)});
}

QString TrajectoryExport::csvHeader()
{
    return QStringLiteral("t_s,ball,x_px,y_px,vx_px_per_s,vy_px_per_s");
}

void TrajectoryExport::writeCsv(QTextStream& out) const
{
    // 17 significant digits: reading the file back gives the same doubles.
    auto num = [](double v) { return QString::number(v, 'g', 17); };
    out << csvHeader() << '\n';
    for (const Row& r : m_rows)
        out << num(r.t) << ',' << r.ball << ',' << num(r.x) << ',' << num(r.y) << ',' << num(r.vx) << ','
            << num(r.vy) << '\n';
}

std::optional<QString> TrajectoryExport::save(const QString& path) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    QTextStream out(&file);
    writeCsv(out);
    out.flush();
    if (out.status() != QTextStream::Ok || !file.commit())
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    return std::nullopt;
}

} // namespace forcelab
