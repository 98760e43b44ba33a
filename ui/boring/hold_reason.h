#pragma once

#include <QString>

#include "core/control/in_process_compensation.h"
#include "core/run/boring_run.h"

namespace tt::ui {

/// The state of one compensation cycle in the operator's words.
struct CycleWords {
    bool holding = false;  ///< no valid deflection (or the CNC did not take it): the offset stays
    QString headline;      ///< "Compensating" / "Holding the offset at 0.162 mm"
    QString reason;        ///< why it holds, plainly (taper, slide not moving, silent device, ...)
    QString detail;        ///< what the device itself reports, for the commissioning engineer; may be empty
};

/// Says what a cycle did: compensating (and whether at the rate or range limit) or holding the
/// offset, and why: taper or contour, slide not moving, dither window too short, waiting for
/// strokes, device silent, no probe data, no table, CNC output not ready or refusing the offset.
/// Worded here from the engine's kinds and data, translated; only the devices' own messages (which
/// the device layer translates) are passed on, as the detail.
CycleWords describeCycle(const core::CompensationCycle& cycle, core::BoringMethod method);

/// Why a run cannot start, in the operator's words, from the builder's refusal.
QString describeRefusal(const core::BoringRunRefused& refusal);

/// A device state in a few words ("in error", "still connecting").
QString deviceStateWords(core::DeviceState state);

}  // namespace tt::ui
