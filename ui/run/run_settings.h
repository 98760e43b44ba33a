#pragma once

#include <QMetaType>
#include <QString>
#include <QVector>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "core/common/notice.h"
#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_state.h"
#include "core/ports/device_health.h"
#include "core/ports/shaft_machine.h"
#include "core/run/shaft_scenario.h"

namespace tt::ui {

/// The key of the lathe the Run page assembles from the devices of the Devices page (the CNC output and
/// gauge chosen there, each part confirmed by the operator); every other key is a machine a device plugin
/// offers whole (devices::ShaftMachineOffer, such as the built-in simulator's lathe).
inline const QString kDevicesMachineKey = QStringLiteral("real");

/// The setting (QSettings key) "Sound on rework or scrap": the Run page beeps for every part judged rework or
/// scrap (View menu of the main window).
inline const QString kSoundOnOutOfTolerance = QStringLiteral("run/soundOnOutOfTolerance");

/// Makes the machine of a run for its scenario; called in the loop's thread.
using MachineMaker = std::function<std::shared_ptr<core::ShaftMachine>(const core::ShaftScenario& scenario)>;

/// What the operator chose for a run on the Run page.
struct RunSettings {
    QString machineKey = QStringLiteral("simulated-lathe");  ///< an offer's key, or kDevicesMachineKey
    QString machineName;                                     ///< as the page names it
    bool operatorCycle = false;  ///< the operator confirms each part (the lathe assembled from the devices)
    QString preset = QStringLiteral("paper-2012-group1");  ///< scenario preset (physical lathe)
    QString controller = QStringLiteral("lqg");            ///< "lqg", "ewma", "open"
    int delay = 2;                                         ///< transport delay z, parts
    double speed = 360.0;      ///< machine seconds per wall second (machines with an adjustable speed)
    std::uint64_t seed = 1;    ///< the simulator's random sources
    bool manualEntry = false;  ///< diameters typed in instead of the machine's gauge
    QString databasePath;      ///< SQLite history file; empty: nothing stored
    QString outputDeviceId;    ///< assembled lathe: the CNC output (id on the Devices page)
    QString gaugeDeviceId;     ///< assembled lathe: the gauge (id on the Devices page); empty: diameters typed by hand
    QString outputName;        ///< their names on the Devices page (stored with the run)
    QString gaugeName;
    /// The loop pauses on a scrap part (besides the preset's loop.pause_on_scrap).
    bool pauseOnScrap = false;
    /// The controller tuning applied on the Controller page (ui/controller/controller_tuning.h); none: the
    /// preset's.
    std::optional<core::RunToRunSetup> tuning;
    /// The run ends after this part (a resumed run planned with an end); none: until stopped.
    std::optional<qint64> lastPartNumber;
    /// The EWMA lambda (a resumed run keeps its own); none: the preset's.
    std::optional<double> ewmaWeight;
};

/// The loop as the page shows it, sent by the loop thread after every change.
struct LoopSnapshot {
    core::LoopState state = core::LoopState::Idle;
    core::Notice status;                 ///< why the loop is in its state (worded by ui/run/notice_text.h)
    qint64 nextPart = 1;                 ///< the part that will be started next
    qint64 partsFinished = 0;            ///< in this session
    std::optional<qint64> awaitingPart;  ///< the part waiting longest for its diameters
    int nextPoint = 0;                   ///< its next control point
    bool manualEntry = false;
    double machineS = 0.0;  ///< the machine's time (simulated, or the wall clock since the run started), s
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
    QString machineName;           ///< the machine as the page named it
    bool operatorCycle = false;    ///< the operator confirms each part
    bool adjustableSpeed = false;  ///< the machine's time runs at a settable multiple of the wall clock
};

}  // namespace tt::ui

Q_DECLARE_METATYPE(tt::ui::RunSettings)
Q_DECLARE_METATYPE(tt::ui::LoopSnapshot)
Q_DECLARE_METATYPE(tt::ui::RunLayout)
