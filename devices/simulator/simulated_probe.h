#pragma once

#include <QVariantMap>
#include <deque>

#include "devices/api/probe_status.h"
#include "devices/parsers/probe_session.h"
#include "devices/simulator/mandrel_emulator.h"
#include "devices/simulator/simulated_device.h"

namespace tt::devices {

/// The simulator's probe mandrel: the emulated microcontroller (MandrelEmulator) on an
/// in-memory wire, driven by the same protocol session as the serial plugin, so corrupt frames,
/// silence and table uploads behave as on the machine. True deflections come from the
/// injectable source (setDeflectionSource) or, stand-alone, the constant deflections set.
/// Settings: rateHz, deflection1Mm, deflection2Mm, silenceTimeoutMs.
class SimulatedProbe final : public SimulatedDevice, public core::DeflectionProbe, public TableUploadTarget {
public:
    SimulatedProbe(const QVariantMap& settings, const DeviceContext& context);

    core::DeviceHealth health() const override { return DeviceBase::health(); }
    std::optional<core::ProbeSample> takeSample() override;
    void testConnection() override;
    void close() override;
    core::DeflectionProbe* deflectionProbe() override { return this; }
    TableUploadTarget* tableUploadTarget() override { return this; }
    QList<DeviceStatistic> statistics() const override;
    void setDeflectionSource(std::function<std::array<double, 2>(double)> source) override;

    void uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    TableUploadStatus uploadStatus() const override;
    std::optional<MandrelTableInfo> tableInfo() const override;
    std::optional<MandrelInfo> mandrelInfo() const override;

    /// The emulated microcontroller (tests inspect the stored table).
    const MandrelEmulator& emulator() const { return m_emulator; }

protected:
    void tick() override;
    void connected() override;

private:
    void exchange(double nowS);

    MandrelEmulator m_emulator;
    probe::ProbeSession m_session;
    std::function<std::array<double, 2>(double)> m_source;
    double m_lastTickS = 0.0;
    std::deque<core::ProbeSample> m_samples;
    std::uint64_t m_overflow = 0;
};

}  // namespace tt::devices
