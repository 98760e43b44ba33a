#include "devices/linuxcnc/linuxcnc_output_device.h"

#include <QCoreApplication>

#include "devices/linuxcnc/linuxcnc_settings.h"

namespace tt::devices::linuxcnc {

namespace {

QString yesNo(bool value) {
    return value ? QCoreApplication::translate("LinuxCnc", "yes") : QCoreApplication::translate("LinuxCnc", "no");
}

QString machineWords(const MachineStatus& s) {
    if (s.estop) return QCoreApplication::translate("LinuxCnc", "E-stop on");
    return s.machineOn ? QCoreApplication::translate("LinuxCnc", "on") : QCoreApplication::translate("LinuxCnc", "off");
}

QString programWords(ProgramStatus p) {
    switch (p) {
        case ProgramStatus::Idle:
            return QCoreApplication::translate("LinuxCnc", "idle");
        case ProgramStatus::Running:
            return QCoreApplication::translate("LinuxCnc", "running");
        case ProgramStatus::Paused:
            return QCoreApplication::translate("LinuxCnc", "paused");
    }
    return {};
}

QString unitsWords(LinearUnits u) {
    return u == LinearUnits::Inch ? QCoreApplication::translate("LinuxCnc", "inch")
                                  : (u == LinearUnits::Centimetre ? QCoreApplication::translate("LinuxCnc", "cm")
                                                                  : QCoreApplication::translate("LinuxCnc", "mm"));
}

}  // namespace

core::DeviceHealth LinuxCncCycle::health() const {
    return m_device.DeviceBase::health();
}

core::OutputResult LinuxCncCycle::startPart(std::int64_t partNumber) {
    if (m_device.m_programPath.isEmpty())
        return {false, QCoreApplication::translate("LinuxCnc",
                                                   "no part program is set for LinuxCNC; the operator runs the parts")
                           .toStdString()};
    if (!m_device.m_pending)
        return {false, QCoreApplication::translate("LinuxCnc", "no corrections were sent for part %1")
                           .arg(partNumber)
                           .toStdString()};
    PartJob job;
    job.correction = *m_device.m_pending;
    job.correction.partNumber = partNumber;
    job.programPath = m_device.m_programPath.toStdString();
    job.pressCycleStart = m_device.m_pressCycleStart;
    m_device.m_session.submit(std::move(job));
    return {true, {}};
}

std::optional<core::FinishedPart> LinuxCncCycle::takeFinishedPart() {
    for (const PartResult& r : m_device.m_session.takeResults())
        m_device.m_started.push_back(r.partNumber);
    if (m_device.m_started.empty()) return std::nullopt;
    const std::int64_t part = m_device.m_started.front();
    m_device.m_started.erase(m_device.m_started.begin());
    return core::FinishedPart{part, m_device.now()};
}

LinuxCncOutputDevice::LinuxCncOutputDevice(const QVariantMap& settings, const DeviceContext& context)
    : DeviceBase(DeviceKind::CorrectionOutput, context),
      m_settings(settings),
      m_session(sessionSettings(settings)),
      m_programPath(settings.value(QStringLiteral("programPath")).toString().trimmed()),
      m_pressCycleStart(settings.value(QStringLiteral("pressCycleStart")).toBool()) {
    m_poll.setInterval(100);
    QObject::connect(&m_poll, &QTimer::timeout, [this] { refresh(); });
}

LinuxCncOutputDevice::~LinuxCncOutputDevice() {
    m_poll.stop();
    m_session.stop();
}

void LinuxCncOutputDevice::open() {
    setState(core::DeviceState::Connecting,
             QCoreApplication::translate("LinuxCnc", "connecting to %1").arg(endpointText(m_settings)));
    m_session.start();
    m_poll.start();
}

void LinuxCncOutputDevice::close() {
    m_poll.stop();
    m_session.stop();
    setState(core::DeviceState::Disconnected);
}

void LinuxCncOutputDevice::testConnection() {
    open();
    m_session.reconnect();
}

void LinuxCncOutputDevice::refresh() {
    const SessionSnapshot s = m_session.snapshot();
    setState(s.health.state, QString::fromStdString(s.health.message));
    if (!s.lastProblem.empty() && QString::fromStdString(s.lastProblem) != lastError())
        reportError(QString::fromStdString(s.lastProblem));
    if (s.lastWrite) {
        setLiveValue(QString::fromStdString(s.lastWrite->message));
    } else if (s.status && s.positionMm) {
        setLiveValue(QCoreApplication::translate("LinuxCnc", "%1; X %2 Z %3 mm")
                         .arg(programWords(s.status->program))
                         .arg((*s.positionMm)[0], 0, 'f', 3)
                         .arg((*s.positionMm)[1], 0, 'f', 3));
    }
}

core::OutputResult LinuxCncOutputDevice::refuse(const QString& message) {
    ++m_refused;
    reportError(message);
    return {false, message.toStdString()};
}

core::OutputResult LinuxCncOutputDevice::sendPartCorrection(const core::PartCorrection& correction) {
    const CorrectionSettings& c = m_session.settings().corrections;
    const std::vector<double> values = valuesToWrite(correction, c.mode);
    if (values.empty())
        return refuse(QCoreApplication::translate("LinuxCnc", "part %1: no corrections").arg(correction.partNumber));
    if (const std::string problem = limitProblem(values, m_lastAccepted, c); !problem.empty())
        return refuse(QCoreApplication::translate("LinuxCnc", "%1: part %2: %3; nothing written")
                          .arg(endpointText(m_settings))
                          .arg(correction.partNumber)
                          .arg(QString::fromStdString(problem)));
    m_lastAccepted = values;
    m_pending = correction;
    if (m_programPath.isEmpty()) {
        PartJob write;  // only the write: no program
        write.correction = correction;
        write.pressCycleStart = false;
        m_session.submit(write);
    }
    return {true, {}};
}

core::OutputResult LinuxCncOutputDevice::sendDynamicOffset(double) {
    return refuse(QCoreApplication::translate(
        "LinuxCnc", "LinuxCNC takes corrections between parts; a dynamic X offset needs a PLC (Modbus output)"));
}

QList<DeviceStatistic> LinuxCncOutputDevice::statistics() const {
    const SessionSnapshot s = m_session.snapshot();
    QList<DeviceStatistic> out;
    if (s.identity)
        out << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "LinuxCNC"),
                               QCoreApplication::translate("LinuxCnc", "remote shell %1, protocol %2")
                                   .arg(QString::fromStdString(s.identity->server),
                                        QString::fromStdString(s.identity->protocol))}
            << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Machine units"),
                               unitsWords(s.identity->machineUnits)};
    if (s.status)
        out << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Machine"), machineWords(*s.status)}
            << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Homed"), yesNo(s.status->allHomed())}
            << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Program"), programWords(s.status->program)};
    if (s.positionMm)
        out << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Position"),
                               QCoreApplication::translate("LinuxCnc", "X %1 Z %2 mm")
                                   .arg((*s.positionMm)[0], 0, 'f', 3)
                                   .arg((*s.positionMm)[1], 0, 'f', 3)};
    const CorrectionSettings& c = m_session.settings().corrections;
    out << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Program units"),
                           QStringLiteral("%1, %2").arg(
                               c.conventions.inch ? QCoreApplication::translate("LinuxCnc", "inch (G20)")
                                                  : QCoreApplication::translate("LinuxCnc", "mm (G21)"),
                               c.conventions.diameterMode ? QCoreApplication::translate("LinuxCnc", "diameter (G7)")
                                                          : QCoreApplication::translate("LinuxCnc", "radius (G8)"))};
    out << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Writes verified"),
                           QString::number(s.counters.writesVerified)}
        << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Writes refused"),
                           QString::number(s.counters.writesRefused + m_refused)}
        << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Read-backs that differed"),
                           QString::number(s.counters.readBacksDiffered)}
        << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Writes held (machine not ready)"),
                           QString::number(s.counters.writesHeld)}
        << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Connection resets"),
                           QString::number(s.counters.connectionResets)}
        << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Parts cut"), QString::number(s.counters.partsCut)}
        << DeviceStatistic{QCoreApplication::translate("LinuxCnc", "Parts aborted"),
                           QString::number(s.counters.partsAborted)};
    return out;
}

}  // namespace tt::devices::linuxcnc
