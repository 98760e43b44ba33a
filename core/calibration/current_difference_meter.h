#pragma once

#include "core/ports/drive_current.h"

namespace tt::core {

/// Why the dithering cross feed gives no current difference now.
enum class StrokeProblem {
    None,
    NotCylindrical,     ///< forward and reverse speeds differ, or the slide moves one way too long
    SlideNotMoving,     ///< the dither does not move the slide
    WindowTooShort,     ///< too few samples at constant velocity in a stroke
    WaitingForStrokes,  ///< not yet a forward and a reverse stroke
};

/// What a meter says after a sample.
struct StrokePairReading {
    bool newPair = false;                         ///< a forward and a reverse stroke completed with this sample
    double currentDifferenceA = 0.0;              ///< ΔI = (I_fwd − I_rev) / 2 of the latest pair, A (when newPair)
    StrokeProblem problem = StrokeProblem::None;  ///< why there is no current difference now
};

/// The current difference of the dithering cross feed, one value per stroke pair (paper 001,
/// way 1): what the k_p calibration averages at each known load. Implemented in core/control
/// over the dither force estimator (DitherCurrentDifference).
class CurrentDifferenceMeter {
public:
    virtual ~CurrentDifferenceMeter() = default;
    /// Forgets every stroke (a new load).
    virtual void reset() = 0;
    /// Feeds one drive sample, in time order.
    virtual StrokePairReading update(const DriveSample& sample) = 0;
};

}  // namespace tt::core
