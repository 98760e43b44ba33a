// The closed loop (core/loop/loop_engine.h) on the simulated lathe with the gauge readings taken
// through the device plugins: the built-in simulator's gauge and the serial gauge plugin with an
// emulated micrometer on a real pseudo-terminal. Both must give the loop exactly what the
// station's own micrometer gives it (same corrections, part for part). Unplugging the serial
// gauge mid-run pauses the loop; plugging it in again lets it finish with the same result.
#include <gtest/gtest.h>

#include <QTest>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>

#include "core/control/run_to_run_plant.h"
#include "core/loop/loop_clock.h"
#include "core/loop/loop_engine.h"
#include "core/sim/shaft/lathe_simulator.h"
#include "core/sim/shaft/lathe_station.h"
#include "devices/api/simulated_instrument.h"
#include "devices/gauge_serial/gauge_serial_factory.h"
#include "devices/simulator/micrometer_emulator.h"
#include "devices/simulator/simulator_plugin.h"
#include "support/pty_pair.h"

namespace tt::devices {
namespace {

using core::LoopState;

/// u_i(n) = u_i(n-1) - g e_i / 2: the textbook integral run-to-run controller (plant gain 2,
/// radial correction to diameter, paper 000), enough to close the loop.
class Integrator final : public core::RunToRunController {
public:
    explicit Integrator(int points) : m_u(Eigen::VectorXd::Zero(points)) {}
    std::string name() const override { return "integrator"; }
    int pointCount() const override { return static_cast<int>(m_u.size()); }
    core::MeasurementVerdict addMeasurement(const core::PartMeasurement& m) override {
        core::MeasurementVerdict v;
        for (Eigen::Index i = 0; i < m.deviationMm.size(); ++i) {
            const double e = m.deviationMm(i);
            const bool ok = std::isfinite(e);
            v.accepted.push_back(ok);
            v.reasons.push_back(ok ? core::Notice() : core::Notice(core::NoticeKind::NotMeasured));
            if (ok) m_u(i) -= 0.5 * e / 2.0;
        }
        return v;
    }
    Eigen::VectorXd nextCorrection(std::int64_t) override { return m_u; }
    core::ControllerState saveState() const override {
        return {"integrator", std::vector<double>(m_u.data(), m_u.data() + m_u.size())};
    }
    void restoreState(const core::ControllerState& s) override {
        for (Eigen::Index i = 0; i < m_u.size(); ++i)
            m_u(i) = s.values.at(static_cast<std::size_t>(i));
    }

private:
    Eigen::VectorXd m_u;
};

constexpr std::int64_t kParts = 12;

/// The simulated lathe and its measuring station (paper 000 shaft, no random disturbance: the
/// micrometer's own noise and 0.001 mm resolution remain).
struct Shop {
    Shop() {
        setup.beamElementMm = 2.5;
        setup.seed = 3;
        const std::vector<double> points = core::paperControlPointsMm(325.0);
        sim = std::make_unique<core::LatheSimulator>(setup, points, core::LatheDisturbanceModel::none(5));
        station = std::make_unique<core::LatheStation>(*sim, setup.micrometer, 3, clock, points);
        station->setKeptParts(1000);
        config.pointZMm = points;
        config.partLengthMm = 325.0;
        config.nominalDiameterMm = 27.0;
        config.delayParts = 1;
        config.lastPartNumber = kParts;
    }
    core::RunDescription run() const { return {"test", "integrator", 1, 27.0, 325.0, config.pointZMm, "{}"}; }
    /// The corrections the CNC got, part by part.
    std::vector<std::vector<double>> sent() const {
        std::vector<std::vector<double>> out;
        for (const auto& c : station->sentCorrections())
            out.push_back(c.pointCorrectionMm);
        return out;
    }

    core::ManualClock clock;
    core::LatheSetup setup;
    std::unique_ptr<core::LatheSimulator> sim;
    std::unique_ptr<core::LatheStation> station;
    core::LoopConfig config;
};

/// Runs the engine with the clock jumping from event to event. Before each step the readings the
/// station's operator takes are handed to `deliver` (nothing: the engine reads the station's gauge
/// directly). `hook` runs after each step; when it returns true (it did something) the engine is
/// stepped again at the same time.
void drive(core::LoopEngine& engine, Shop& shop, const std::function<void(double)>& deliver,
           const std::function<bool()>& hook = {}) {
    for (int i = 0; i < 100000; ++i) {
        if (deliver)
            while (auto r = shop.station->gauge().takeReading())
                deliver(r->diameterMm);
        engine.step();
        if (engine.complete() || engine.state() == LoopState::Fault) return;
        if (hook && hook()) continue;
        const double next = std::min(shop.station->nextEventTimeS(), engine.nextWakeS());
        if (!std::isfinite(next)) return;
        shop.clock.advanceTo(next);
    }
}

std::vector<std::vector<double>> referenceRun() {
    Shop shop;
    core::LoopEngine engine(
        shop.config,
        core::LoopPorts{shop.station->machine(), shop.station->output(), shop.station->gauge(), shop.clock, nullptr},
        std::make_unique<Integrator>(5));
    engine.start(shop.run());
    drive(engine, shop, {});
    EXPECT_TRUE(engine.complete()) << engine.detail();
    return shop.sent();
}

/// The same corrections part for part, within 1e-12 mm: the plugins parse the micrometer's text
/// (26812 / 1000), the station's gauge rounds in binary; both are the same 0.001 mm reading.
void expectSameCorrections(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t part = 0; part < a.size(); ++part) {
        ASSERT_EQ(a[part].size(), b[part].size());
        for (std::size_t i = 0; i < a[part].size(); ++i)
            EXPECT_NEAR(a[part][i], b[part][i], 1e-12) << "part " << part + 1 << ", point " << i;
    }
}

int accepted(const Device& d) {
    return d.statistics().front().value.toInt();  // "Readings accepted"
}

TEST(ClosedLoopWithGaugePlugins, SimulatorPluginAndSerialGaugeGiveTheSameResult) {
    const auto reference = referenceRun();
    ASSERT_EQ(reference.size(), static_cast<std::size_t>(kParts));
    // The loop really corrects: the middle point's correction moves away from zero.
    EXPECT_LT(reference.back()[2], -0.01);

    // The simulator plugin's gauge, fed with the diameters the station's operator measures.
    std::vector<std::vector<double>> viaSimulator;
    {
        Shop shop;
        SimulatorPlugin plugin;
        auto gauge = plugin.create(DeviceKind::Gauge, {}, DeviceContext{&shop.clock});
        gauge->open();
        ASSERT_TRUE(gauge->health().ready());
        core::LoopEngine engine(shop.config,
                                core::LoopPorts{shop.station->machine(), shop.station->output(),
                                                *gauge->diameterGauge(), shop.clock, nullptr},
                                std::make_unique<Integrator>(5));
        engine.start(shop.run());
        drive(engine, shop, [&](double d) {
            tt::devices::simulatedInstrument(*gauge)->simulationInputs().setDiameterSource([d] { return d; });
            gauge->diameterGauge()->requestReading();
        });
        ASSERT_TRUE(engine.complete()) << engine.detail();
        viaSimulator = shop.sent();
    }

    // The serial gauge plugin: the micrometer on a pseudo-terminal sends each reading (DATA button).
    std::vector<std::vector<double>> viaSerial;
    {
        Shop shop;
        test::PtyPair pty(QStringLiteral("ttyLOOPGAUGE"));
        MicrometerEmulator micrometer(MicrometerEmulator::Format::Ascii);
        GaugeSerialFactory factory;
        auto gauge =
            factory.create(DeviceKind::Gauge, {{QStringLiteral("port"), pty.portName()}}, DeviceContext{&shop.clock});
        gauge->open();
        ASSERT_TRUE(QTest::qWaitFor([&] { return gauge->health().ready(); }, 3000)) << gauge->health().message;
        core::LoopEngine engine(shop.config,
                                core::LoopPorts{shop.station->machine(), shop.station->output(),
                                                *gauge->diameterGauge(), shop.clock, nullptr},
                                std::make_unique<Integrator>(5));
        engine.start(shop.run());
        drive(engine, shop, [&](double d) {
            const int before = accepted(*gauge);
            micrometer.setSource([d] { return d; });
            pty.send(micrometer.pressDataButton());
            ASSERT_TRUE(QTest::qWaitFor([&] { return accepted(*gauge) == before + 1; }, 3000));
        });
        ASSERT_TRUE(engine.complete()) << engine.detail();
        viaSerial = shop.sent();
    }

    EXPECT_EQ(viaSimulator, viaSerial);  // bit for bit: both parse the same 0.001 mm text
    expectSameCorrections(viaSerial, reference);
}

TEST(ClosedLoopWithGaugePlugins, UnplugMidRunPausesTheLoopAndReconnectLetsItFinish) {
    const auto reference = referenceRun();
    Shop shop;
    test::PtyPair pty(QStringLiteral("ttyLOOPGAUGE"));
    MicrometerEmulator micrometer(MicrometerEmulator::Format::Ascii);
    GaugeSerialFactory factory;
    auto gauge =
        factory.create(DeviceKind::Gauge, {{QStringLiteral("port"), pty.portName()}}, DeviceContext{&shop.clock});
    gauge->open();
    ASSERT_TRUE(QTest::qWaitFor([&] { return gauge->health().ready(); }, 3000));
    pty.releaseSlave();
    core::LoopEngine engine(
        shop.config,
        core::LoopPorts{shop.station->machine(), shop.station->output(), *gauge->diameterGauge(), shop.clock, nullptr},
        std::make_unique<Integrator>(5));
    engine.start(shop.run());

    std::deque<double> held;  // readings the operator could not send while the cable was out
    bool unplugged = false;
    bool sawPause = false;
    std::size_t sentWhenPaused = 0;
    auto send = [&](double d) {
        const int before = accepted(*gauge);
        micrometer.setSource([d] { return d; });
        pty.send(micrometer.pressDataButton());
        ASSERT_TRUE(QTest::qWaitFor([&] { return accepted(*gauge) == before + 1; }, 3000));
    };
    drive(
        engine, shop,
        [&](double d) {
            if (unplugged)
                held.push_back(d);
            else
                send(d);
        },
        [&] {
            // Pull the cable while part 5 is on the lathe.
            if (!unplugged && !sawPause && engine.nextPartNumber() == 6) {
                pty.unplug();
                unplugged = true;
                EXPECT_TRUE(QTest::qWaitFor([&] { return gauge->health().state == core::DeviceState::Error; }, 3000));
                return true;
            }
            if (unplugged && engine.state() == LoopState::Paused && std::isinf(shop.station->nextEventTimeS())) {
                // Everything measured is waiting; the loop holds: no new part, the last correction kept.
                sawPause = true;
                EXPECT_NE(engine.detail().find("the gauge is not ready"), std::string::npos) << engine.detail();
                sentWhenPaused = shop.sent().size();
                pty.plug();
                EXPECT_TRUE(QTest::qWaitFor([&] { return gauge->health().ready(); }, 5000)) << gauge->health().message;
                unplugged = false;
                while (!held.empty()) {
                    send(held.front());
                    held.pop_front();
                }
                return true;
            }
            return false;
        });
    ASSERT_TRUE(sawPause) << "the loop never paused; state " << static_cast<int>(engine.state()) << ": "
                          << engine.detail();
    EXPECT_EQ(sentWhenPaused, 5u);  // parts 1..5 got corrections, part 6 waited
    ASSERT_TRUE(engine.complete()) << engine.detail();
    expectSameCorrections(shop.sent(), reference);  // nothing was lost or changed by the interruption
}

}  // namespace
}  // namespace tt::devices
