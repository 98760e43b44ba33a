#include "devices/simulator/simulated_gauge.h"

#include <QCoreApplication>

#include "devices/simulator/simulator_settings.h"

namespace tt::devices {

namespace {
constexpr std::size_t kMaxQueued = 256;
}

SimulatedGauge::SimulatedGauge(const QVariantMap& settings, const DeviceContext& context)
    : SimulatedDevice(DeviceKind::Gauge, context, 50),
      m_instrument(micrometerFormat(settings), instrumentUnit(settings),
                   settings.value(QStringLiteral("decimals"), 3).toInt()),
      m_decoder(gaugeFormat(settings), instrumentUnit(settings), jobUnit(settings)),
      m_replyTimeoutS(settings.value(QStringLiteral("replyTimeoutMs"), 1000).toDouble() / 1000.0) {
    const double nominal = settings.value(QStringLiteral("nominalDiameterMm"), 27.0).toDouble();
    m_source = [nominal] { return nominal; };
}

void SimulatedGauge::setDiameterSource(std::function<double()> source) {
    if (source) m_source = std::move(source);
}

void SimulatedGauge::connected() {
    m_decoder.reset();
    m_requestedAtS.reset();
    setState(core::DeviceState::Ready, QCoreApplication::translate("Simulator", "simulated gauge ready"));
}

void SimulatedGauge::testConnection() {
    if (!isOpen()) open();
    requestReading();
}

void SimulatedGauge::requestReading() {
    if (!isOpen() || unplugged()) return;
    m_requestedAtS = now();
    if (faults().silent) return;  // the instrument does not answer: tick() times out
    double trueMm = faults().stuck && m_lastTrueMm ? *m_lastTrueMm : m_source();
    if (!faults().stuck) trueMm += noise();
    m_lastTrueMm = trueMm;
    m_instrument.setSource([trueMm] { return trueMm; });
    if (faults().malformed) m_instrument.corruptNext();
    const std::vector<std::uint8_t> wire = m_instrument.pressDataButton();
    m_requestedAtS.reset();
    for (const GaugeDecoded& d : m_decoder.feed(wire)) {
        if (!d.diameterMm) {
            reportError(QString::fromStdString(d.error));
            continue;
        }
        if (m_readings.size() == kMaxQueued) m_readings.pop_front();
        m_readings.push_back({*d.diameterMm, now()});
        setLiveValue(QCoreApplication::translate("Simulator", "%1 mm").arg(*d.diameterMm, 0, 'f', d.decimals));
    }
    setState(core::DeviceState::Ready, QCoreApplication::translate("Simulator", "simulated gauge ready"));
}

std::optional<core::GaugeReading> SimulatedGauge::takeReading() {
    if (m_readings.empty()) return std::nullopt;
    const core::GaugeReading r = m_readings.front();
    m_readings.pop_front();
    return r;
}

void SimulatedGauge::tick() {
    if (state() == core::DeviceState::Connecting) connected();
    if (m_requestedAtS && now() - *m_requestedAtS > m_replyTimeoutS) {
        setState(core::DeviceState::Error,
                 QCoreApplication::translate("Simulator", "no answer from the simulated gauge for %1 s")
                     .arg(now() - *m_requestedAtS, 0, 'f', 1));
    }
}

QList<DeviceStatistic> SimulatedGauge::statistics() const {
    return {{QCoreApplication::translate("Simulator", "Readings accepted"), QString::number(m_decoder.accepted())},
            {QCoreApplication::translate("Simulator", "Malformed frames"), QString::number(m_decoder.malformed())},
            {QCoreApplication::translate("Simulator", "Readings refused"), QString::number(m_decoder.refused())}};
}

}  // namespace tt::devices
