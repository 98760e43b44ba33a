#include "devices/simulator/simulated_output.h"

#include <QCoreApplication>
#include <cmath>

#include "devices/parsers/modbus_registers.h"

namespace tt::devices {

namespace {

using namespace modbus;
constexpr double kScaleMm = 0.0001;  // register counts of 0.1 um

}  // namespace

SimulatedOutput::SimulatedOutput(const QVariantMap& settings, const DeviceContext& context)
    : SimulatedDevice(DeviceKind::CorrectionOutput, context, 100),
      m_maxCorrectionMm(settings.value(QStringLiteral("maxCorrectionMm"), 0.5).toDouble()) {}

void SimulatedOutput::connected() {
    setState(core::DeviceState::Ready,
             QCoreApplication::translate("Simulator", "the simulated CNC accepts corrections"));
}

void SimulatedOutput::testConnection() {
    if (!isOpen()) open();
}

core::OutputResult SimulatedOutput::refuse(const QString& message, bool fault) {
    ++m_failures;
    reportError(message);
    if (fault) setState(core::DeviceState::Error, message);
    return {false, message.toStdString()};
}

std::optional<QString> SimulatedOutput::writeAndVerify(const std::vector<double>& valuesMm, std::vector<double>& plc) {
    std::vector<std::vector<std::uint16_t>> written;
    for (const double v : valuesMm)
        written.push_back(encodeValue(v, RegisterType::Int32, WordOrder::HighWordFirst, kScaleMm));
    // The PLC stores the registers; a malformed transfer changes one of them.
    std::vector<std::vector<std::uint16_t>> stored = written;
    if (faults().malformed && !stored.empty()) stored.back()[1] ^= 0x0001;
    for (std::size_t i = 0; i < written.size(); ++i) {
        if (stored[i] != written[i]) {
            const double readBack =
                decodeValue(stored[i], RegisterType::Int32, WordOrder::HighWordFirst, kScaleMm).value();
            return QCoreApplication::translate("Simulator", "read-back mismatch at value %1: wrote %2 mm, read %3 mm")
                .arg(i + 1)
                .arg(valuesMm[i], 0, 'f', 4)
                .arg(readBack, 0, 'f', 4);
        }
    }
    plc.clear();
    for (const auto& words : stored)
        plc.push_back(decodeValue(words, RegisterType::Int32, WordOrder::HighWordFirst, kScaleMm).value());
    return std::nullopt;
}

core::OutputResult SimulatedOutput::sendPartCorrection(const core::PartCorrection& correction) {
    if (!isOpen() || unplugged())
        return refuse(QCoreApplication::translate("Simulator", "%1 is not connected").arg(what()), false);
    if (faults().silent) return refuse(QCoreApplication::translate("Simulator", "no answer from %1").arg(what()), true);
    if (correction.pointCorrectionMm.empty() || correction.pointCorrectionMm.size() != correction.pointZMm.size())
        return refuse(
            QCoreApplication::translate("Simulator", "part %1: the corrections do not match the control points")
                .arg(correction.partNumber),
            false);
    for (const double c : correction.pointCorrectionMm) {
        if (!std::isfinite(c) || std::fabs(c) > m_maxCorrectionMm)
            return refuse(QCoreApplication::translate(
                              "Simulator", "part %1: correction %2 mm is beyond the limit of %3 mm; nothing sent")
                              .arg(correction.partNumber)
                              .arg(c, 0, 'f', 4)
                              .arg(m_maxCorrectionMm, 0, 'f', 3),
                          false);
    }
    ++m_writes;
    std::vector<double> plc;
    if (const auto mismatch = writeAndVerify(correction.pointCorrectionMm, plc)) return refuse(*mismatch, true);
    m_plcCorrections = plc;
    if (m_partSink) m_partSink(correction);
    setLiveValue(QCoreApplication::translate("Simulator", "part %1: %2 corrections verified")
                     .arg(correction.partNumber)
                     .arg(plc.size()));
    setState(core::DeviceState::Ready,
             QCoreApplication::translate("Simulator", "the simulated CNC accepts corrections"));
    return {true, {}};
}

core::OutputResult SimulatedOutput::sendDynamicOffset(double xOffsetMm) {
    if (!isOpen() || unplugged())
        return refuse(QCoreApplication::translate("Simulator", "%1 is not connected").arg(what()), false);
    if (faults().silent) return refuse(QCoreApplication::translate("Simulator", "no answer from %1").arg(what()), true);
    if (!std::isfinite(xOffsetMm) || std::fabs(xOffsetMm) > m_maxCorrectionMm)
        return refuse(
            QCoreApplication::translate("Simulator", "offset %1 mm is beyond the limit of %2 mm; nothing sent")
                .arg(xOffsetMm, 0, 'f', 4)
                .arg(m_maxCorrectionMm, 0, 'f', 3),
            false);
    ++m_writes;
    std::vector<double> plc;
    if (const auto mismatch = writeAndVerify({xOffsetMm}, plc)) return refuse(*mismatch, true);
    m_plcOffset = plc.front();
    if (m_offsetSink) m_offsetSink(xOffsetMm);
    setLiveValue(QCoreApplication::translate("Simulator", "X offset %1 mm").arg(xOffsetMm, 0, 'f', 4));
    setState(core::DeviceState::Ready,
             QCoreApplication::translate("Simulator", "the simulated CNC accepts corrections"));
    return {true, {}};
}

QList<DeviceStatistic> SimulatedOutput::statistics() const {
    return {{QCoreApplication::translate("Simulator", "Writes"), QString::number(m_writes)},
            {QCoreApplication::translate("Simulator", "Refused or failed"), QString::number(m_failures)}};
}

}  // namespace tt::devices
