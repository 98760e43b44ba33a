#pragma once

#include <QVariantMap>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "core/sim/rigs/known_load_rig.h"
#include "devices/simulator/simulated_boring_station.h"
#include "devices/simulator/simulated_device.h"

namespace tt::devices {

/// The cross-feed of paper 001, way 1, stand-alone: while boring a cylinder the stopped
/// cross-feed oscillates with a small amplitude A and period T as a triangle (uniform motion
/// each way, velocity +-4A/T); the motor current is the cutting component plus friction that
/// changes sign with the direction: I = I_cut + sign(v) I_friction.
core::DriveSample oscillatingCrossFeed(double timeS, double amplitudeMm, double periodS, double frictionCurrentA,
                                       double cuttingCurrentA);

/// The simulator's drive-current readout: polled like the Modbus plugin (every pollMs), each
/// sample travels as registers (current int16 0.01 A, velocity float32 mm/s, position int32
/// 0.1 um) and is decoded back, so a malformed register value is refused as on the machine.
/// The drive state comes from the injectable source (setDriveSource) or the oscillation above.
/// Settings: pollMs, amplitudeMm, periodS, frictionCurrentA, cuttingCurrentA, stand.
/// On its calibration stand (CalibrationStand; setting "stand", default on) a hydraulic jack pushes the tool holder
/// with a known load while the cross feed dithers: from the first load on, the read-out measures core::KnownLoadRig
/// (the heavy-boring cross feed: true k_p 150 N/A, Coulomb friction 975 N, current noise 0.3 A; dither 0.01 mm, 0.5 s;
/// one sample per poll period as the PLC cycle) until the jack is released. It is also a simulated boring station
/// (boringTruth(): the heavy cross feed of paper 001 with dither), whose passes follow this read-out's fault switches.
class SimulatedDrive final : public SimulatedDevice, public core::DriveCurrentReadout, public CalibrationStand {
public:
    SimulatedDrive(const QVariantMap& settings, const DeviceContext& context);

    core::DeviceHealth health() const override { return DeviceBase::health(); }
    std::optional<core::DriveSample> takeSample() override;
    void testConnection() override;
    core::DriveCurrentReadout* driveCurrentReadout() override { return this; }
    QList<DeviceStatistic> statistics() const override;
    void setDriveSource(std::function<core::DriveSample(double)> source) override;
    BoringTruth* boringTruth() override { return &m_station; }
    CalibrationStand* calibrationStand() override { return m_onStand ? this : nullptr; }

    bool bendsBar() const override { return false; }
    void bendBar(int plane, double tipDeflectionMm) override;
    bool appliesLoad() const override { return true; }
    void applyLoadN(double loadN) override;
    bool engaged() const override { return m_stand != nullptr; }
    void release() override;

protected:
    void tick() override;
    void connected() override;
    void stateChecked() override { m_station.follow(health()); }

private:
    /// The drive states due now: the stand's samples since the last poll, or one from the source.
    std::vector<core::DriveSample> truths(double nowS);
    /// Sends one state over the "wire" and queues what the read-out decodes; false when refused.
    bool relay(core::DriveSample truth);

    std::function<core::DriveSample(double)> m_source;
    std::unique_ptr<core::KnownLoadRig> m_stand;  ///< the stand's hydraulic jack, when engaged
    double m_standOriginS = 0.0;                  ///< device time of the stand's time 0
    double m_cycleS;
    bool m_onStand;
    std::deque<core::DriveSample> m_samples;
    std::optional<core::DriveSample> m_last;
    int m_missedPolls = 0;
    std::uint64_t m_polls = 0;
    std::uint64_t m_refused = 0;
    SimulatedBoringStation m_station{core::BoringMethod::Current, [this] { return health(); }};
};

}  // namespace tt::devices
