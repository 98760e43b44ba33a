#include "devices/modbus/modbus_drive_device.h"

#include <QCoreApplication>

#include "devices/modbus/modbus_settings.h"
#include "devices/parsers/drive_units.h"

namespace tt::devices {

namespace {

constexpr std::size_t kMaxQueued = 8192;
constexpr int kFailedPollsForError = 3;

double unitFactor(const QVariantMap& settings, const QString& prefix, DriveQuantity quantity) {
    return toEngineUnitFactor(quantity, settings.value(prefix + QStringLiteral("Unit")).toString().toStdString())
        .value_or(1.0);
}

}  // namespace

ModbusDriveDevice::ModbusDriveDevice(const QVariantMap& settings, const DeviceContext& context)
    : DeviceBase(DeviceKind::DriveCurrent, context) {
    m_current = {registerSpec(settings, QStringLiteral("current")),
                 unitFactor(settings, QStringLiteral("current"), DriveQuantity::Current)};
    m_velocity = {registerSpec(settings, QStringLiteral("velocity")),
                  unitFactor(settings, QStringLiteral("velocity"), DriveQuantity::Velocity)};
    m_position = {registerSpec(settings, QStringLiteral("position")),
                  unitFactor(settings, QStringLiteral("position"), DriveQuantity::Position)};
    const std::vector<modbus::RegisterSpec> specs{m_current.spec, m_velocity.spec, m_position.spec};
    m_blocks = modbus::planReads(specs);
    m_link = std::make_unique<ModbusLink>(
        settings, ModbusLink::Callbacks{[this] { connected(); }, [this](const QString& reason) { lost(reason); }});
    m_timer.setInterval(settings.value(QStringLiteral("pollMs"), 20).toInt());
    m_timer.setTimerType(Qt::PreciseTimer);
    QObject::connect(&m_timer, &QTimer::timeout, [this] { poll(); });
}

ModbusDriveDevice::~ModbusDriveDevice() {
    m_timer.stop();
}

void ModbusDriveDevice::open() {
    setState(core::DeviceState::Connecting,
             QCoreApplication::translate("Modbus", "connecting to %1").arg(m_link->endpoint()));
    m_link->open();
}

void ModbusDriveDevice::close() {
    m_timer.stop();
    m_link->close();
    m_polling = false;
    setState(core::DeviceState::Disconnected);
}

void ModbusDriveDevice::testConnection() {
    if (!m_link->isConnected()) {
        open();
        return;
    }
    poll();
}

void ModbusDriveDevice::connected() {
    m_failedInARow = 0;
    m_polling = false;
    setState(core::DeviceState::Connecting,
             QCoreApplication::translate("Modbus", "connected to %1; reading").arg(m_link->endpoint()));
    m_timer.start();
    poll();
}

void ModbusDriveDevice::lost(const QString& reason) {
    m_timer.stop();
    m_polling = false;
    setState(core::DeviceState::Error, reason);
}

void ModbusDriveDevice::poll() {
    if (m_polling) {
        ++m_overruns;  // the previous poll is still waiting: never queue up requests
        return;
    }
    if (!m_link->isConnected()) return;
    ++m_polls;
    m_polling = true;
    m_sentAtS = now();
    m_pending = m_blocks.size();
    m_words.assign(m_blocks.size(), {});
    m_pollError.clear();
    m_pollTimedOut = false;
    m_pollException = false;
    for (std::size_t i = 0; i < m_blocks.size(); ++i) {
        if (!m_link->read(m_blocks[i], [this, i](const ModbusResult& r) { blockDone(i, r); })) {
            m_pollError =
                QCoreApplication::translate("Modbus", "cannot send the request to %1").arg(m_link->endpoint());
            if (--m_pending == 0) finishPoll();
        }
    }
}

void ModbusDriveDevice::blockDone(std::size_t index, const ModbusResult& result) {
    if (!m_polling) return;
    if (result.ok) {
        m_words[index] = result.words;
    } else {
        m_pollError = result.error;
        m_pollTimedOut = m_pollTimedOut || result.timeout;
        m_pollException = m_pollException || result.exceptionCode.has_value();
    }
    if (--m_pending == 0) finishPoll();
}

void ModbusDriveDevice::finishPoll() {
    m_polling = false;
    const double receivedAtS = now();
    if (!m_pollError.isEmpty()) {
        if (m_pollTimedOut) ++m_timeouts;
        if (m_pollException) ++m_exceptions;
        reportError(m_pollError);
        // A Modbus exception is an answer: the map is wrong, not the line. Timeouts count up.
        if (m_pollException || ++m_failedInARow >= kFailedPollsForError) {
            setState(core::DeviceState::Error, m_pollException
                                                   ? m_pollError
                                                   : QCoreApplication::translate("Modbus", "%1 (%2 polls in a row)")
                                                         .arg(m_pollError)
                                                         .arg(m_failedInARow));
        }
        return;
    }
    m_failedInARow = 0;
    auto value = [this](const Quantity& q) -> std::optional<double> {
        for (std::size_t i = 0; i < m_blocks.size(); ++i) {
            const modbus::ReadBlock& b = m_blocks[i];
            if (q.spec.table != b.table || q.spec.address < b.start || q.spec.address >= b.start + b.count) continue;
            const auto r = modbus::extractValue(q.spec, b, m_words[i]);
            if (!r) {
                reportError(
                    QCoreApplication::translate("Modbus", "sample refused: %1").arg(QString::fromStdString(r.error())));
                return std::nullopt;
            }
            return r.value() * q.toEngineUnit;
        }
        return std::nullopt;
    };
    const auto current = value(m_current);
    const auto velocity = value(m_velocity);
    const auto position = value(m_position);
    if (!current || !velocity || !position) {
        ++m_refused;
        setState(core::DeviceState::Ready, QCoreApplication::translate("Modbus", "polling %1").arg(m_link->endpoint()));
        return;
    }
    const core::DriveSample s{(m_sentAtS + receivedAtS) / 2.0, *current, *velocity, *position};
    if (m_samples.size() == kMaxQueued) m_samples.pop_front();
    m_samples.push_back(s);
    ++m_samplesOk;
    setLiveValue(QCoreApplication::translate("Modbus", "%1 A, %2 mm/s, %3 mm")
                     .arg(s.currentA, 0, 'f', 2)
                     .arg(s.velocityMmPerS, 0, 'f', 3)
                     .arg(s.positionMm, 0, 'f', 4));
    setState(core::DeviceState::Ready, QCoreApplication::translate("Modbus", "polling %1").arg(m_link->endpoint()));
}

std::optional<core::DriveSample> ModbusDriveDevice::takeSample() {
    if (m_samples.empty()) return std::nullopt;
    const core::DriveSample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

QList<DeviceStatistic> ModbusDriveDevice::statistics() const {
    return {
        {QCoreApplication::translate("Modbus", "Polls"), QString::number(m_polls)},
        {QCoreApplication::translate("Modbus", "Samples"), QString::number(m_samplesOk)},
        {QCoreApplication::translate("Modbus", "Timeouts"), QString::number(m_timeouts)},
        {QCoreApplication::translate("Modbus", "Modbus exceptions"), QString::number(m_exceptions)},
        {QCoreApplication::translate("Modbus", "Samples refused"), QString::number(m_refused)},
        {QCoreApplication::translate("Modbus", "Polls skipped (previous still running)"), QString::number(m_overruns)}};
}

}  // namespace tt::devices
