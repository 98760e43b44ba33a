#pragma once

#include <QVariantMap>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "devices/api/device_base.h"
#include "devices/modbus/modbus_link.h"
#include "devices/parsers/modbus_registers.h"

namespace tt::devices {

/// Corrections to the CNC's PLC over Modbus TCP or RTU, with read-back verification:
///   - target "points": the per-point radial corrections of the next part (run-to-run, paper
///     000) into consecutive holding registers, then optionally the part number as a handshake;
///   - target "offset": the dynamic X tool offset the PLC applies every cycle (in-process
///     boring compensation, paper 001), latest value wins when the caller is faster than the bus.
/// Every write is read back and compared; a mismatch puts the device in error with both values.
/// The port's calls never block: sendPartCorrection/sendDynamicOffset check the values and
/// queue the write (ok = accepted); the outcome of the write and its verification shows in
/// health(), liveValue() and lastError(), and lastVerified() counts verified writes.
/// Settings: modbusConnectionFields(), target, pointsAddress, maxPoints, offsetAddress,
/// writePartNumber, partAddress, value* register fields, maxCorrectionMm.
class ModbusOutputDevice final : public DeviceBase, public core::CorrectionOutput {
public:
    ModbusOutputDevice(const QVariantMap& settings, const DeviceContext& context);

    void open() override;
    void close() override;
    void testConnection() override;
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    core::OutputResult sendPartCorrection(const core::PartCorrection& correction) override;
    core::OutputResult sendDynamicOffset(double xOffsetMm) override;
    core::CorrectionOutput* correctionOutput() override { return this; }
    QList<DeviceStatistic> statistics() const override;

    /// Writes whose read-back matched.
    std::uint64_t verifiedWrites() const { return m_verified; }

private:
    /// One register write and its read-back.
    struct Step {
        std::uint16_t start = 0;
        std::vector<std::uint16_t> words;
        QString what;  ///< "corrections of part 12"
    };
    /// A job: the steps of one part correction or one offset, and what to show when done.
    struct Job {
        std::vector<Step> steps;
        QString done;
    };
    core::OutputResult accept(Job job, bool isOffset);
    void startNext();
    void runStep();
    void written(const ModbusResult& result);
    void readBack(const ModbusResult& result);
    void fail(const QString& message);
    core::OutputResult refuse(const QString& message);

    std::unique_ptr<ModbusLink> m_link;
    bool m_pointsTarget;
    std::uint16_t m_pointsAddress;
    int m_maxPoints;
    std::uint16_t m_offsetAddress;
    bool m_writePartNumber;
    std::uint16_t m_partAddress;
    modbus::RegisterType m_type;
    modbus::WordOrder m_order;
    double m_scaleMm;
    double m_maxCorrectionMm;
    std::optional<Job> m_current;
    std::size_t m_step = 0;
    std::deque<Job> m_queue;
    std::optional<Job> m_pendingOffset;  ///< latest offset waiting for the bus
    std::uint64_t m_verified = 0;
    std::uint64_t m_failed = 0;
};

}  // namespace tt::devices
