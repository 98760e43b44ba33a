#pragma once

#include <QMetaType>
#include <QString>
#include <QVector>
#include <cstdint>
#include <optional>

#include "core/common/notice.h"
#include "core/loop/loop_state.h"
#include "core/ports/device_health.h"

namespace tt::runtime {

/// The loop as the page shows it, sent by the loop thread after every change.
struct LoopSnapshot {
    core::LoopState state = core::LoopState::Idle;
    core::Notice status;                  ///< why the loop is in its state (worded by ui/run/notice_text.h)
    qint64 nextPart = 1;                  ///< the part that will be started next
    qint64 partsFinished = 0;             ///< in this session
    std::optional<qint64> awaitingPart;   ///< the part waiting longest for its diameters
    int nextPoint = 0;                    ///< its next control point
    std::optional<qint64> partOnMachine;  ///< machines whose cycle the operator runs: the part being machined
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
    QString machineName;                    ///< the machine as the page named it
    bool partsConfirmedByOperator = false;  ///< the operator confirms each part
    bool adjustableSpeed = false;           ///< the machine's time runs at a settable multiple of the wall clock
};

}  // namespace tt::runtime

Q_DECLARE_METATYPE(tt::runtime::LoopSnapshot)
Q_DECLARE_METATYPE(tt::runtime::RunLayout)
