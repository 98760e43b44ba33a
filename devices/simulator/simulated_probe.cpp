#include "devices/simulator/simulated_probe.h"

#include <QCoreApplication>
#include <cmath>
#include <stdexcept>

namespace tt::devices {

namespace {

/// Commands answered per tick: the in-memory wire is fast, so an upload moves on by several
/// chunks per 10 ms tick (a 16-bit table of 1025 chunks takes about 0.7 s).
constexpr int kRoundTripsPerTick = 16;
/// How far the stand's screw jack bends the bar either way, mm.
constexpr double kJackTravelMm = 2.0;

}  // namespace

SimulatedProbe::SimulatedProbe(const QVariantMap& settings, const DeviceContext& context)
    : SimulatedDevice(DeviceKind::Probe, context, 10),
      ProbeSessionPorts(settings),
      m_onStand(settings.value(QStringLiteral("stand"), true).toBool()) {
    const std::array<double, 2> constant{settings.value(QStringLiteral("deflection1Mm"), 0.02).toDouble(),
                                         settings.value(QStringLiteral("deflection2Mm"), -0.005).toDouble()};
    m_source = [constant](double) { return constant; };
    // The emulator's clock runs from open(); the source sees the device clock's time.
    m_emulator.setDeflectionSource([this](double) {
        std::array<double, 2> d = m_jack ? *m_jack : m_source(now());
        for (double& v : d)
            v += noise();
        return d;
    });
    // Stand-alone the mandrel already holds a calibrated table (version 1), as on delivery.
    m_emulator.preloadTable(MandrelEmulator::deliveryTableImage(), 1);
}

void SimulatedProbe::setDeflectionSource(std::function<std::array<double, 2>(double)> source) {
    if (source) m_source = std::move(source);
}

void SimulatedProbe::bendBar(int plane, double tipDeflectionMm) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("the bending plane must be 0 (X) or 1 (Y)");
    if (!std::isfinite(tipDeflectionMm) || std::abs(tipDeflectionMm) > kJackTravelMm)
        throw std::invalid_argument("the screw jack bends the bar by at most ±2 mm");
    std::array<double, 2> d{};
    d[static_cast<std::size_t>(plane)] = tipDeflectionMm;
    m_jack = d;
}

void SimulatedProbe::applyLoadN(double) {
    throw std::invalid_argument("the probe mandrel's stand has no hydraulic jack");
}

void SimulatedProbe::connected() {
    m_lastTickS = now();
    m_session.start(m_lastTickS);
}

void SimulatedProbe::close() {
    m_session.stop(now());
    exchange(now());
    SimulatedDevice::close();
}

void SimulatedProbe::testConnection() {
    if (!isOpen()) open();
    m_session.requestTableInfo();
}

void SimulatedProbe::exchange(double nowS) {
    m_emulator.setSilent(faults().silent);
    m_emulator.setStuck(faults().stuck);
    if (faults().malformed) m_emulator.corruptNextFrames(1);
    for (int i = 0; i < kRoundTripsPerTick; ++i) {
        const std::vector<std::uint8_t> commands = m_session.poll(nowS);  // also runs the watchdogs
        if (commands.empty()) break;
        m_session.receive(m_emulator.receive(commands), nowS);
    }
    const std::vector<std::uint8_t> samples = m_emulator.advance(nowS - m_lastTickS);
    m_lastTickS = nowS;
    m_session.receive(samples, nowS);
}

void SimulatedProbe::tick() {
    const double t = now();
    exchange(t);
    queueSessionSamples();
    if (const QString live = lastSampleText(); !live.isEmpty()) setLiveValue(live);
    if (!m_session.lastError().empty() && QString::fromStdString(m_session.lastError()) != lastError())
        reportError(QString::fromStdString(m_session.lastError()));
    switch (m_session.link()) {
        case probe::ProbeSession::Link::Streaming:
            setState(core::DeviceState::Ready, QCoreApplication::translate("Simulator", "streaming"));
            break;
        case probe::ProbeSession::Link::Handshake:
            setState(core::DeviceState::Connecting,
                     QCoreApplication::translate("Simulator", "starting the probe mandrel"));
            break;
        case probe::ProbeSession::Link::Silent:
            // Said in the terminal's language (the session's own sentence is English).
            setState(core::DeviceState::Error,
                     QCoreApplication::translate("Simulator", "no data from %1 (silent)").arg(what()));
            break;
        case probe::ProbeSession::Link::Failed:
            setState(core::DeviceState::Error, QString::fromStdString(m_session.problem()));
            break;
        case probe::ProbeSession::Link::Idle:
            break;
    }
}

}  // namespace tt::devices
