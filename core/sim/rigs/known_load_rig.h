#pragma once

#include <deque>

#include "core/ports/drive_current.h"
#include "core/sim/boring/cross_feed_drive.h"
#include "core/sim/boring/dither_profile.h"

namespace tt::core {

/// The k_p calibration set-up on the simulator: the cross slide dithers while a known radial load
/// (hydraulic jack with a dynamometer) pushes the tool holder towards the axis; the drive read-out
/// delivers one sample per PLC cycle. Deterministic for a seed.
class KnownLoadRig final : public DriveCurrentReadout {
public:
    /// The rig's drive, its dither, the PLC cycle (s) the samples come at and the seed of the drive's noise.
    KnownLoadRig(const CrossFeedDriveConfig& drive, const DitherConfig& dither, double plcCycleS,
                 unsigned long long seed);

    /// The load from now on, N (towards the axis: positive).
    void setLoadN(double loadN);
    /// The load now, N.
    double loadN() const { return m_loadN; }
    /// Advances the simulation by `seconds`, queueing a drive sample every PLC cycle.
    void advance(double seconds);
    /// Simulated time, s.
    double timeS() const { return m_timeS; }

    DeviceHealth health() const override { return {DeviceState::Ready, {}}; }
    std::optional<DriveSample> takeSample() override;

private:
    CrossFeedDrive m_drive;
    DitherProfile m_dither;
    double m_cycleS;
    double m_timeS = 0.0;
    double m_nextSampleS;
    double m_loadN = 0.0;
    std::deque<DriveSample> m_samples;
};

}  // namespace tt::core
