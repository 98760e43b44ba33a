#pragma once

#include <QVariantMap>
#include <optional>
#include <vector>

#include "devices/simulator/simulated_device.h"

namespace tt::devices {

/// The simulator's correction output: a CNC/PLC that takes per-point corrections and a dynamic
/// X offset into registers (int32, 0.1 um) and is read back for verification, like the Modbus
/// output. Accepted corrections go to the injectable sinks (e.g. the lathe simulator).
/// Settings: maxCorrectionMm.
class SimulatedOutput final : public SimulatedDevice, public core::CorrectionOutput {
public:
    SimulatedOutput(const QVariantMap& settings, const DeviceContext& context);

    core::DeviceHealth health() const override { return DeviceBase::health(); }
    core::OutputResult sendPartCorrection(const core::PartCorrection& correction) override;
    core::OutputResult sendDynamicOffset(double xOffsetMm) override;
    void testConnection() override;
    core::CorrectionOutput* correctionOutput() override { return this; }
    QList<DeviceStatistic> statistics() const override;
    void setCorrectionSink(std::function<void(const core::PartCorrection&)> sink) override {
        m_partSink = std::move(sink);
    }
    void setOffsetSink(std::function<void(double)> sink) override { m_offsetSink = std::move(sink); }

    /// What the simulated PLC holds: the last verified corrections and offset, mm.
    const std::vector<double>& plcCorrectionsMm() const { return m_plcCorrections; }
    std::optional<double> plcOffsetMm() const { return m_plcOffset; }

protected:
    void tick() override {}
    void connected() override;

private:
    core::OutputResult refuse(const QString& message, bool fault);
    std::optional<QString> writeAndVerify(const std::vector<double>& valuesMm, std::vector<double>& plc);

    double m_maxCorrectionMm;
    std::vector<double> m_plcCorrections;
    std::optional<double> m_plcOffset;
    std::function<void(const core::PartCorrection&)> m_partSink;
    std::function<void(double)> m_offsetSink;
    std::uint64_t m_writes = 0;
    std::uint64_t m_failures = 0;
};

}  // namespace tt::devices
