#pragma once

#include <QTimer>
#include <QVariantMap>
#include <memory>
#include <optional>
#include <vector>

#include "core/ports/machine_cycle.h"
#include "devices/api/device_base.h"
#include "devices/linuxcnc/linuxcnc_session.h"

namespace tt::devices::linuxcnc {

class LinuxCncOutputDevice;

/// The part cycle of a LinuxCNC device (a shop's own part program): startPart writes the corrections last sent
/// and opens the configured program, pressing cycle start when set to (otherwise the operator does); a part is
/// finished when the program ran to its end, aborted (and cut again) when it stopped on an E-stop, a machine
/// off or an error. Thread-safe (the session is).
class LinuxCncCycle final : public core::MachineCycle {
public:
    explicit LinuxCncCycle(LinuxCncOutputDevice& device) : m_device(device) {}
    core::DeviceHealth health() const override;
    /// Refused when no part program is set (programPath) or no corrections were sent for the part.
    core::OutputResult startPart(std::int64_t partNumber) override;
    std::optional<core::FinishedPart> takeFinishedPart() override;

private:
    LinuxCncOutputDevice& m_device;
};

/// LinuxCNC as the lathe's CNC on the Devices page (kind CorrectionOutput): LinuxCNC's remote shell over TCP
/// (linuxcncsh; devices/parsers/linuxcnc_reply.h), corrections written between parts and read back (profile:
/// numbered parameters #500..; wear: the tool's X wear), never while a program runs, limits checked before the
/// write. Without a part program set, each correction is written once when it is sent (the operator runs the
/// parts); with one, the part cycle (cycle()) writes it before the part and runs the program. Test connection
/// says what it found in the user's words (server and protocol version, machine state, homed or not, units)
/// in health(), liveValue() and statistics(). The session runs in a thread of its own; this object, like every
/// device, is used from the thread that made it (a timer there brings the session's state in).
/// Settings: linuxCncSchema().
class LinuxCncOutputDevice final : public DeviceBase, public core::CorrectionOutput {
public:
    LinuxCncOutputDevice(const QVariantMap& settings, const DeviceContext& context);
    ~LinuxCncOutputDevice() override;

    void open() override;
    void close() override;
    void testConnection() override;
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    /// Accepts (ok) corrections within the limits and queues their write; the write's outcome shows in health(),
    /// lastError(), statistics() and takeWrites().
    core::OutputResult sendPartCorrection(const core::PartCorrection& correction) override;
    core::OutputResult sendDynamicOffset(double xOffsetMm) override;
    core::CorrectionOutput* correctionOutput() override { return this; }
    QList<DeviceStatistic> statistics() const override;

    /// The part cycle (program started / finished / aborted).
    core::MachineCycle& cycle() { return m_cycle; }
    /// Every write tried since the last call, for the history (and the audit trail of a hand-made write).
    std::vector<WriteRecord> takeWrites() { return m_session.takeWrites(); }
    /// Problems worth an alarm since the last call.
    std::vector<std::string> takeIncidents() { return m_session.takeIncidents(); }
    /// The program events since the last call.
    std::vector<CycleEvent> takeEvents() { return m_session.takeEvents(); }
    LinuxCncSession& session() { return m_session; }

private:
    friend class LinuxCncCycle;
    core::OutputResult refuse(const QString& message);
    void refresh();

    QVariantMap m_settings;
    LinuxCncSession m_session;
    LinuxCncCycle m_cycle{*this};
    QString m_programPath;
    bool m_pressCycleStart = false;
    QTimer m_poll;
    std::optional<core::PartCorrection> m_pending;
    std::optional<std::vector<double>> m_lastAccepted;
    std::vector<std::int64_t> m_started;
    std::uint64_t m_refused = 0;
};

}  // namespace tt::devices::linuxcnc
