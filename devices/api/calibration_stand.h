#pragma once

namespace tt::devices {

/// The calibration stand a device sits on, a capability of the built-in simulator's devices
/// (Device::calibrationStand(); null for a device on a machine, where the operator loads the bar
/// and reads the instruments): the screw jack that bends the boring bar to a tip deflection
/// (probe mandrel) or the hydraulic jack that pushes the tool holder towards the spindle axis with
/// a known load while the cross feed dithers (drive-current read-out). While a jack is engaged
/// the device measures the stand instead of its simulation inputs; release() gives them back.
class CalibrationStand {
public:
    virtual ~CalibrationStand() = default;

    /// The stand has a screw jack that bends the bar (probe mandrels).
    virtual bool bendsBar() const = 0;
    /// Bends the bar to `tipDeflectionMm` in `plane` (0 = X, 1 = Y; the other plane unloaded).
    /// Throws std::invalid_argument without a screw jack, for another plane, or beyond the jack's
    /// travel (±2 mm).
    virtual void bendBar(int plane, double tipDeflectionMm) = 0;

    /// The stand has a hydraulic jack that loads the tool holder (drive read-outs).
    virtual bool appliesLoad() const = 0;
    /// Pushes the tool holder towards the axis with `loadN` (negative: away from it). Throws
    /// std::invalid_argument without a hydraulic jack or beyond its force (±20 000 N).
    virtual void applyLoadN(double loadN) = 0;

    /// A jack is engaged.
    virtual bool engaged() const = 0;
    /// Takes the jack away: the device follows its simulation inputs again.
    virtual void release() = 0;
};

}  // namespace tt::devices
