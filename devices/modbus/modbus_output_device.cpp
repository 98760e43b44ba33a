#include "devices/modbus/modbus_output_device.h"

#include <QCoreApplication>
#include <cmath>

#include "devices/modbus/modbus_settings.h"

namespace tt::devices {

namespace {

QString wordsText(const std::vector<std::uint16_t>& words) {
    QStringList parts;
    for (const std::uint16_t w : words)
        parts << QString::number(w);
    return parts.join(QLatin1Char(' '));
}

}  // namespace

ModbusOutputDevice::ModbusOutputDevice(const QVariantMap& settings, const DeviceContext& context)
    : DeviceBase(DeviceKind::CorrectionOutput, context),
      m_pointsTarget(settings.value(QStringLiteral("target")).toString() != QLatin1String("offset")),
      m_pointsAddress(static_cast<std::uint16_t>(settings.value(QStringLiteral("pointsAddress")).toUInt())),
      m_maxPoints(settings.value(QStringLiteral("maxPoints"), 5).toInt()),
      m_offsetAddress(static_cast<std::uint16_t>(settings.value(QStringLiteral("offsetAddress")).toUInt())),
      m_writePartNumber(settings.value(QStringLiteral("writePartNumber")).toBool()),
      m_partAddress(static_cast<std::uint16_t>(settings.value(QStringLiteral("partAddress")).toUInt())),
      m_maxCorrectionMm(settings.value(QStringLiteral("maxCorrectionMm"), 0.5).toDouble()) {
    const modbus::RegisterSpec spec = registerSpec(settings, QStringLiteral("value"));
    m_type = spec.type;
    m_order = spec.order;
    m_scaleMm = spec.scale;
    m_link = std::make_unique<ModbusLink>(
        settings, ModbusLink::Callbacks{
                      [this] {
                          setState(core::DeviceState::Ready,
                                   QCoreApplication::translate("Modbus", "connected to %1").arg(m_link->endpoint()));
                          startNext();
                      },
                      [this](const QString& reason) {
                          m_current.reset();
                          setState(core::DeviceState::Error, reason);
                      }});
}

void ModbusOutputDevice::open() {
    setState(core::DeviceState::Connecting,
             QCoreApplication::translate("Modbus", "connecting to %1").arg(m_link->endpoint()));
    m_link->open();
}

void ModbusOutputDevice::close() {
    m_link->close();
    m_current.reset();
    m_queue.clear();
    m_pendingOffset.reset();
    setState(core::DeviceState::Disconnected);
}

void ModbusOutputDevice::testConnection() {
    if (!m_link->isConnected()) {
        open();
        return;
    }
    // Reading the target registers proves the PLC answers and the addresses exist.
    const std::uint16_t start = m_pointsTarget ? m_pointsAddress : m_offsetAddress;
    const auto count = static_cast<std::uint16_t>(modbus::registerCount(m_type) *
                                                  static_cast<std::size_t>(m_pointsTarget ? m_maxPoints : 1));
    m_link->read({modbus::RegisterTable::Holding, start, count}, [this](const ModbusResult& r) {
        if (r.ok)
            setState(
                core::DeviceState::Ready,
                QCoreApplication::translate("Modbus", "connected to %1; registers readable").arg(m_link->endpoint()));
        else
            fail(r.error);
    });
}

core::OutputResult ModbusOutputDevice::refuse(const QString& message) {
    ++m_failed;
    reportError(message);
    return {false, message.toStdString()};
}

core::OutputResult ModbusOutputDevice::sendPartCorrection(const core::PartCorrection& correction) {
    if (!m_pointsTarget)
        return refuse(QCoreApplication::translate(
            "Modbus", "this output is set up for the dynamic X offset, not per-point corrections"));
    const auto& values = correction.pointCorrectionMm;
    if (values.empty() || static_cast<int>(values.size()) > m_maxPoints)
        return refuse(QCoreApplication::translate("Modbus", "part %1 has %2 corrections; this output takes 1 to %3")
                          .arg(correction.partNumber)
                          .arg(values.size())
                          .arg(m_maxPoints));
    Job job;
    Step step{m_pointsAddress,
              {},
              QCoreApplication::translate("Modbus", "corrections of part %1").arg(correction.partNumber)};
    for (const double v : values) {
        if (!std::isfinite(v) || std::fabs(v) > m_maxCorrectionMm)
            return refuse(QCoreApplication::translate(
                              "Modbus", "part %1: correction %2 mm is beyond the limit of %3 mm; nothing sent")
                              .arg(correction.partNumber)
                              .arg(v, 0, 'f', 4)
                              .arg(m_maxCorrectionMm, 0, 'f', 3));
        try {
            const auto words = modbus::encodeValue(v, m_type, m_order, m_scaleMm);
            step.words.insert(step.words.end(), words.begin(), words.end());
        } catch (const std::invalid_argument& e) {
            return refuse(QCoreApplication::translate("Modbus", "part %1: %2")
                              .arg(correction.partNumber)
                              .arg(QString::fromStdString(e.what())));
        }
    }
    job.steps.push_back(step);
    if (m_writePartNumber) {
        const auto part = static_cast<std::uint32_t>(correction.partNumber);
        job.steps.push_back({m_partAddress,
                             {static_cast<std::uint16_t>(part >> 16), static_cast<std::uint16_t>(part & 0xFFFF)},
                             QCoreApplication::translate("Modbus", "part number %1").arg(correction.partNumber)});
    }
    job.done = QCoreApplication::translate("Modbus", "part %1: %2 corrections written and verified")
                   .arg(correction.partNumber)
                   .arg(values.size());
    return accept(std::move(job), false);
}

core::OutputResult ModbusOutputDevice::sendDynamicOffset(double xOffsetMm) {
    if (m_pointsTarget)
        return refuse(QCoreApplication::translate(
            "Modbus", "this output is set up for per-point corrections, not the dynamic X offset"));
    if (!std::isfinite(xOffsetMm) || std::fabs(xOffsetMm) > m_maxCorrectionMm)
        return refuse(QCoreApplication::translate("Modbus", "X offset %1 mm is beyond the limit of %2 mm; nothing sent")
                          .arg(xOffsetMm, 0, 'f', 4)
                          .arg(m_maxCorrectionMm, 0, 'f', 3));
    Job job;
    try {
        job.steps.push_back({m_offsetAddress, modbus::encodeValue(xOffsetMm, m_type, m_order, m_scaleMm),
                             QCoreApplication::translate("Modbus", "X offset %1 mm").arg(xOffsetMm, 0, 'f', 4)});
    } catch (const std::invalid_argument& e) {
        return refuse(QString::fromStdString(e.what()));
    }
    job.done = QCoreApplication::translate("Modbus", "X offset %1 mm written and verified").arg(xOffsetMm, 0, 'f', 4);
    return accept(std::move(job), true);
}

core::OutputResult ModbusOutputDevice::accept(Job job, bool isOffset) {
    if (state() != core::DeviceState::Ready && state() != core::DeviceState::Error)
        return refuse(QCoreApplication::translate("Modbus", "%1 is not connected").arg(m_link->endpoint()));
    if (!m_link->isConnected())
        return refuse(QCoreApplication::translate("Modbus", "%1 is not connected").arg(m_link->endpoint()));
    if (isOffset)
        m_pendingOffset = std::move(job);  // only the newest offset matters
    else
        m_queue.push_back(std::move(job));
    startNext();
    return {true, {}};
}

void ModbusOutputDevice::startNext() {
    if (m_current || !m_link->isConnected()) return;
    if (!m_queue.empty()) {
        m_current = std::move(m_queue.front());
        m_queue.pop_front();
    } else if (m_pendingOffset) {
        m_current = std::move(*m_pendingOffset);
        m_pendingOffset.reset();
    } else {
        return;
    }
    m_step = 0;
    runStep();
}

void ModbusOutputDevice::runStep() {
    const Step& step = m_current->steps[m_step];
    if (!m_link->write(step.start, step.words, [this](const ModbusResult& r) { written(r); }))
        fail(QCoreApplication::translate("Modbus", "cannot send %1 to %2").arg(step.what, m_link->endpoint()));
}

void ModbusOutputDevice::written(const ModbusResult& result) {
    if (!m_current) return;
    if (!result.ok) {
        fail(result.error);
        return;
    }
    const Step& step = m_current->steps[m_step];
    const modbus::ReadBlock block{modbus::RegisterTable::Holding, step.start,
                                  static_cast<std::uint16_t>(step.words.size())};
    if (!m_link->read(block, [this](const ModbusResult& r) { readBack(r); }))
        fail(QCoreApplication::translate("Modbus", "cannot read back %1 from %2").arg(step.what, m_link->endpoint()));
}

void ModbusOutputDevice::readBack(const ModbusResult& result) {
    if (!m_current) return;
    if (!result.ok) {
        fail(result.error);
        return;
    }
    const Step& step = m_current->steps[m_step];
    if (result.words != step.words) {
        fail(QCoreApplication::translate("Modbus", "read-back mismatch for %1 at register %2: wrote %3, read %4")
                 .arg(step.what)
                 .arg(step.start)
                 .arg(wordsText(step.words), wordsText(result.words)));
        return;
    }
    if (++m_step < m_current->steps.size()) {
        runStep();
        return;
    }
    ++m_verified;
    setLiveValue(m_current->done);
    setState(core::DeviceState::Ready,
             QCoreApplication::translate("Modbus", "connected to %1").arg(m_link->endpoint()));
    m_current.reset();
    startNext();
}

void ModbusOutputDevice::fail(const QString& message) {
    ++m_failed;
    reportError(message);
    setState(core::DeviceState::Error, message);
    m_current.reset();
    startNext();
}

QList<DeviceStatistic> ModbusOutputDevice::statistics() const {
    return {{QCoreApplication::translate("Modbus", "Writes verified"), QString::number(m_verified)},
            {QCoreApplication::translate("Modbus", "Refused or failed"), QString::number(m_failed)}};
}

}  // namespace tt::devices
