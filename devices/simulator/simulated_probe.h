#pragma once

#include <QVariantMap>
#include <optional>

#include "devices/api/probe_status.h"
#include "devices/simulator/mandrel_emulator.h"
#include "devices/simulator/simulated_boring_station.h"
#include "devices/simulator/simulated_device.h"

namespace tt::devices {

/// The simulator's probe mandrel: the emulated microcontroller (MandrelEmulator) on an
/// in-memory wire, driven by the same protocol session as the serial plugin, so corrupt frames,
/// silence and table uploads behave as on the machine. True deflections come from the
/// injectable source (setDeflectionSource) or, stand-alone, the constant deflections set.
/// Settings: rateHz, deflection1Mm, deflection2Mm, silenceTimeoutMs, stand.
/// On its calibration stand (CalibrationStand; setting "stand", default on) a screw jack bends the bar to a tip
/// deflection in one plane; while it is engaged the mandrel measures the jack instead of the deflection source.
/// It is also a simulated boring station (boringTruth(): the slender bar of paper 001 with its own mandrel,
/// calibrated on the simulated stand), whose passes follow this mandrel's fault switches.
class SimulatedProbe final : public SimulatedDevice, public ProbeSessionPorts, public CalibrationStand {
public:
    SimulatedProbe(const QVariantMap& settings, const DeviceContext& context);

    core::DeviceHealth health() const override { return DeviceBase::health(); }
    void testConnection() override;
    void close() override;
    core::DeflectionProbe* deflectionProbe() override { return this; }
    TableUploadTarget* tableUploadTarget() override { return this; }
    QList<DeviceStatistic> statistics() const override { return sessionStatistics(); }
    void setDeflectionSource(std::function<std::array<double, 2>(double)> source) override;
    BoringTruth* boringTruth() override { return &m_station; }
    CalibrationStand* calibrationStand() override { return m_onStand ? this : nullptr; }

    bool bendsBar() const override { return true; }
    void bendBar(int plane, double tipDeflectionMm) override;
    bool appliesLoad() const override { return false; }
    void applyLoadN(double loadN) override;
    bool engaged() const override { return m_jack.has_value(); }
    void release() override { m_jack.reset(); }

    /// The emulated microcontroller (tests inspect the stored table and set its faults).
    const MandrelEmulator& emulator() const { return m_emulator; }
    MandrelEmulator& emulator() { return m_emulator; }

protected:
    void tick() override;
    void connected() override;
    void stateChecked() override { m_station.follow(health()); }

private:
    void exchange(double nowS);

    MandrelEmulator m_emulator;
    std::function<std::array<double, 2>(double)> m_source;
    bool m_onStand;
    std::optional<std::array<double, 2>> m_jack;  ///< the stand's screw jack, when engaged
    double m_lastTickS = 0.0;
    SimulatedBoringStation m_station{core::BoringMethod::Probe, [this] { return health(); }};
};

}  // namespace tt::devices
