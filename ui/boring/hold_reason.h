#pragma once

#include <QString>

#include "core/control/in_process_compensation.h"
#include "ui/boring/boring_rig.h"

namespace tt::ui {

/// The state of one compensation cycle in the operator's words.
struct CycleWords {
    bool holding = false;  ///< no valid deflection (or the CNC refused): the offset stays
    QString headline;      ///< "Compensating" / "Holding the offset at 0.162 mm"
    QString reason;        ///< why it holds, plainly (taper, slide not moving, silent device, ...)
    QString detail;        ///< the engine's own wording, for the commissioning engineer
};

/// Says what a cycle did: compensating (and whether at the rate or range limit) or holding the
/// offset, and why: taper or contour, slide not moving, dither window too short, waiting for
/// strokes, device silent, no probe data, no table, CNC refusing the offset.
CycleWords describeCycle(const core::CompensationCycle& cycle, BoringSource source);

}  // namespace tt::ui
