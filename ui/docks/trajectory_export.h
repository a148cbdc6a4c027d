#pragma once
// Records a trajectory while the simulation runs and writes it as CSV:
//
//     t_s,ball,x_px,y_px,vx_px_per_s,vy_px_per_s
//
// one row per recorded ball per record, in time order. Records are taken when
// the world's time has moved on (once per frame when driven by a controller),
// so a paused simulation adds nothing. Works on a plain World: no window needed.

#include "sim/world/world.h"

#include <QObject>
#include <QString>

#include <optional>
#include <vector>

class QTextStream;

namespace forcelab {

class SimulationController;

class TrajectoryExport : public QObject {
    Q_OBJECT
public:
    struct Row {
        double t = 0.0; ///< s
        int ball = 0;
        double x = 0.0, y = 0.0;   ///< px
        double vx = 0.0, vy = 0.0; ///< px/s
    };

    /// Recording stops here (about 100 MB): the export says so rather than dropping rows silently.
    static constexpr std::size_t kMaxRows = 2'000'000;

    explicit TrajectoryExport(QObject* parent = nullptr);
    /// Records on every `stepped` of `controller` while recording; a new scene
    /// or a reset stops recording (the rows are kept for export).
    explicit TrajectoryExport(SimulationController* controller, QObject* parent = nullptr);

    /// Starts a new recording of `ball` (-1: every ball), dropping old rows,
    /// and records the current state as the first rows.
    void start(const sim::World& world, int ball);
    void stop();
    bool isRecording() const { return m_recording; }
    /// The recorded ball, -1 for all.
    int ball() const { return m_ball; }
    /// True when recording stopped because kMaxRows was reached.
    bool isFull() const { return m_full; }

    /// Appends the current state if the world's time is later than the last record's.
    void record(const sim::World& world);

    const std::vector<Row>& rows() const { return m_rows; }
    void clear();

    static QString csvHeader();
    /// Writes the header and every row (full double precision).
    void writeCsv(QTextStream& out) const;
    /// Writes the CSV to `path`. Returns an error message ("file: why") or nothing.
    std::optional<QString> save(const QString& path) const;

signals:
    void recordingChanged(bool recording);

private:
    std::vector<Row> m_rows;
    double m_lastTime = 0.0;
    int m_ball = -1;
    bool m_recording = false;
    bool m_full = false;
};

} // namespace forcelab
