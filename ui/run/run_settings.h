#pragma once

#include <QMetaType>
#include <QString>
#include <QVector>
#include <cstdint>
#include <optional>

#include "core/loop/loop_state.h"
#include "core/ports/device_health.h"

namespace tt::ui {

/// Where the parts are made: the built-in simulated lathe (its own CNC, gauge and part cycle) or the real
/// lathe (the CNC output and gauge chosen from the Devices page, parts confirmed by the operator).
enum class Machine { Simulated, RealLathe };

/// What the operator chose for a run on the Run page.
struct RunSettings {
    Machine machine = Machine::Simulated;
    QString preset = QStringLiteral("paper-2012-group1");  ///< scenario preset (physical lathe)
    QString controller = QStringLiteral("lqg");            ///< "lqg", "ewma", "open"
    int delay = 2;                                         ///< transport delay z, parts
    double speed = 360.0;                                  ///< simulated seconds per wall second
    std::uint64_t seed = 1;                                ///< the simulator's random sources
    bool manualEntry = false;                              ///< diameters typed in instead of the simulated gauge
    QString databasePath;                                  ///< SQLite history file; empty: nothing stored
    QString outputDeviceId;                                ///< real lathe: the CNC output (id on the Devices page)
    QString gaugeDeviceId;  ///< real lathe: the gauge (id on the Devices page); empty: diameters typed by hand
};

/// The loop as the page shows it, sent by the loop thread after every change.
struct LoopSnapshot {
    core::LoopState state = core::LoopState::Idle;
    QString detail;                      ///< the engine's own words
    qint64 nextPart = 1;                 ///< the part that will be started next
    qint64 partsFinished = 0;            ///< in this session
    std::optional<qint64> awaitingPart;  ///< the part waiting longest for its diameters
    int nextPoint = 0;                   ///< its next control point
    bool manualEntry = false;
    bool realLathe = false;   ///< the run is on the real lathe (its time is the wall clock)
    double simulatedS = 0.0;  ///< simulated time of the run, s
    core::DeviceHealth gauge;
    core::DeviceHealth cnc;
    std::optional<qint64> runId;
};

/// The fixed facts of a started run the page needs to draw it.
struct RunLayout {
    QVector<double> pointZMm;
    double partLengthMm = 0.0;
    double nominalDiameterMm = 0.0;
    double plausibleRangeMm = 0.0;
    double toleranceMm = 0.0;       ///< ± band on diameter the plot shows
    QVector<double> systematicZMm;  ///< the systematic model d(x) sampled, empty without a model
    QVector<double> systematicErrorMm;
    int delay = 1;
    QString controller;
    QString preset;
    Machine machine = Machine::Simulated;
};

}  // namespace tt::ui

Q_DECLARE_METATYPE(tt::ui::RunSettings)
Q_DECLARE_METATYPE(tt::ui::LoopSnapshot)
Q_DECLARE_METATYPE(tt::ui::RunLayout)
