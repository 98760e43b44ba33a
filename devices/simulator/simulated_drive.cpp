#include "devices/simulator/simulated_drive.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "devices/parsers/modbus_registers.h"

namespace tt::devices {

namespace {

constexpr std::size_t kMaxQueued = 8192;
constexpr int kMissedPollsForError = 3;
constexpr double kMaxStandLoadN = 20000.0;
constexpr unsigned long long kStandSeed = 3;  ///< the stand's drive noise, the same on every start

using namespace modbus;

}  // namespace

core::DriveSample oscillatingCrossFeed(double timeS, double amplitudeMm, double periodS, double frictionCurrentA,
                                       double cuttingCurrentA) {
    const double phase = timeS / periodS - std::floor(timeS / periodS);  // 0..1
    const double speed = 4.0 * amplitudeMm / periodS;
    core::DriveSample s;
    s.timeS = timeS;
    // Triangle: -A at phase 0, +A at phase 0.5, back to -A at 1.
    if (phase < 0.5) {
        s.positionMm = -amplitudeMm + speed * phase * periodS;
        s.velocityMmPerS = speed;
    } else {
        s.positionMm = amplitudeMm - speed * (phase - 0.5) * periodS;
        s.velocityMmPerS = -speed;
    }
    s.currentA = cuttingCurrentA + (s.velocityMmPerS > 0.0 ? frictionCurrentA : -frictionCurrentA);
    return s;
}

SimulatedDrive::SimulatedDrive(const QVariantMap& settings, const DeviceContext& context)
    : SimulatedDevice(DeviceKind::DriveCurrent, context, settings.value(QStringLiteral("pollMs"), 20).toInt()),
      m_cycleS(settings.value(QStringLiteral("pollMs"), 20).toInt() / 1000.0),
      m_onStand(settings.value(QStringLiteral("stand"), true).toBool()) {
    const double amplitude = settings.value(QStringLiteral("amplitudeMm"), 0.02).toDouble();
    const double period = settings.value(QStringLiteral("periodS"), 1.0).toDouble();
    const double friction = settings.value(QStringLiteral("frictionCurrentA"), 2.0).toDouble();
    const double cutting = settings.value(QStringLiteral("cuttingCurrentA"), 0.6).toDouble();
    m_source = [=](double t) { return oscillatingCrossFeed(t, amplitude, period, friction, cutting); };
}

void SimulatedDrive::setDriveSource(std::function<core::DriveSample(double)> source) {
    if (source) m_source = std::move(source);
}

void SimulatedDrive::connected() {
    m_missedPolls = 0;
    setState(core::DeviceState::Ready, QCoreApplication::translate("Simulator", "polling the simulated drive"));
}

void SimulatedDrive::testConnection() {
    if (!isOpen()) open();
    tick();
}

void SimulatedDrive::tick() {
    ++m_polls;
    if (faults().silent) {
        if (++m_missedPolls >= kMissedPollsForError)
            setState(core::DeviceState::Error,
                     QCoreApplication::translate("Simulator", "no answer from the simulated drive for %1 polls")
                         .arg(m_missedPolls));
        return;
    }
    m_missedPolls = 0;
    for (const core::DriveSample& truth : truths(now()))
        if (!relay(truth)) break;
    setState(core::DeviceState::Ready, QCoreApplication::translate("Simulator", "polling the simulated drive"));
}

std::vector<core::DriveSample> SimulatedDrive::truths(double nowS) {
    if (faults().stuck && m_last) {
        core::DriveSample s = *m_last;
        s.timeS = nowS;
        return {s};
    }
    std::vector<core::DriveSample> out;
    if (!m_stand) {
        out.push_back(m_source(nowS));
        out.back().timeS = nowS;
    } else {
        m_stand->advance(std::max(0.0, nowS - m_standOriginS - m_stand->timeS()));
        while (std::optional<core::DriveSample> s = m_stand->takeSample()) {
            s->timeS += m_standOriginS;
            out.push_back(*s);
        }
    }
    for (core::DriveSample& s : out)
        s.currentA += noise();
    return out;
}

bool SimulatedDrive::relay(core::DriveSample truth) {
    const double t = truth.timeS;
    // Over the "wire": registers out of the drive, decoded by the readout.
    std::vector<std::uint16_t> current =
        encodeValue(truth.currentA, RegisterType::Int16, WordOrder::HighWordFirst, 0.01);
    std::vector<std::uint16_t> velocity =
        encodeValue(truth.velocityMmPerS, RegisterType::Float32, WordOrder::HighWordFirst, 1.0);
    std::vector<std::uint16_t> position =
        encodeValue(truth.positionMm, RegisterType::Int32, WordOrder::HighWordFirst, 0.0001);
    if (faults().malformed) velocity = {0x7FC0, 0x0000};  // a NaN where the velocity should be
    const auto i = decodeValue(current, RegisterType::Int16, WordOrder::HighWordFirst, 0.01);
    const auto v = decodeValue(velocity, RegisterType::Float32, WordOrder::HighWordFirst, 1.0);
    const auto x = decodeValue(position, RegisterType::Int32, WordOrder::HighWordFirst, 0.0001);
    if (!i || !v || !x) {
        ++m_refused;
        reportError(QCoreApplication::translate("Simulator", "sample refused: %1")
                        .arg(QString::fromStdString(!i   ? i.error()
                                                    : !v ? "velocity: " + v.error()
                                                         : x.error())));
        return false;
    }
    core::DriveSample s{t, i.value(), v.value(), x.value()};
    m_last = truth;
    if (m_samples.size() == kMaxQueued) m_samples.pop_front();
    m_samples.push_back(s);
    setLiveValue(QCoreApplication::translate("Simulator", "%1 A, %2 mm/s, %3 mm")
                     .arg(s.currentA, 0, 'f', 2)
                     .arg(s.velocityMmPerS, 0, 'f', 3)
                     .arg(s.positionMm, 0, 'f', 4));
    return true;
}

void SimulatedDrive::bendBar(int, double) {
    throw std::invalid_argument("the cross feed's stand has no screw jack");
}

void SimulatedDrive::applyLoadN(double loadN) {
    if (!std::isfinite(loadN) || std::abs(loadN) > kMaxStandLoadN)
        throw std::invalid_argument("the hydraulic jack pushes with at most ±20 000 N");
    if (!m_stand) {
        // The k_p stand: the heavy-boring cross feed dithering 0.01 mm with a 0.5 s period, 60 %
        // of each stroke at constant velocity, sampled once per PLC cycle (the poll period).
        m_stand = std::make_unique<core::KnownLoadRig>(core::CrossFeedDriveConfig{}, core::DitherConfig{0.01, 0.5, 0.6},
                                                       std::clamp(m_cycleS, 0.01, 0.1), kStandSeed);
        m_standOriginS = now();
    }
    m_stand->setLoadN(loadN);
}

void SimulatedDrive::release() {
    m_stand.reset();
}

std::optional<core::DriveSample> SimulatedDrive::takeSample() {
    if (m_samples.empty()) return std::nullopt;
    const core::DriveSample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

QList<DeviceStatistic> SimulatedDrive::statistics() const {
    return {{QCoreApplication::translate("Simulator", "Polls"), QString::number(m_polls)},
            {QCoreApplication::translate("Simulator", "Samples refused"), QString::number(m_refused)}};
}

}  // namespace tt::devices
