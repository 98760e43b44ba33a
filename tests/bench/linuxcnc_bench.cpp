// Writing the five corrections of a part into LinuxCNC and having LinuxCNC compare what it holds with what was
// written, over TCP on loopback (devices/linuxcnc, CorrectionWriter::write): the machine-state check before the
// write (E-stop, power, homing, program), the MDI mode, the write line and the two check lines. Needs the
// headless LinuxCNC of scripts/start-test-linuxcnc.sh (TRUETURN_LINUXCNC_URL); without it the benchmark says so.
#include <benchmark/benchmark.h>

#include <QUrl>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "devices/linuxcnc/linuxcnc_corrections.h"

namespace {

using namespace tt::devices::linuxcnc;

/// E-stop off, machine on, homed.
bool bringUp(LinuxCncController& c) {
    if (c.status().estop) c.request("set estop off");
    c.request("set machine on");
    for (int i = 0; i < 500 && !c.status().machineOn; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (!c.status().allHomed()) {
        c.setMode(TaskMode::Manual);
        c.request("set home -1");
        for (int i = 0; i < 1000 && !c.status().allHomed(); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return notReadyReason(c.status()).empty();
}

void BM_LinuxCncWriteAndReadBackFiveCorrections(benchmark::State& state) {
    const char* url = std::getenv("TRUETURN_LINUXCNC_URL");
    if (!url) {
        state.SkipWithError("no LinuxCNC: eval \"$(scripts/start-test-linuxcnc.sh /tmp/lcnc)\" first");
        return;
    }
    const QUrl parsed(QString::fromUtf8(url));
    ControllerOptions options;
    options.endpoint = {parsed.host().toStdString(), parsed.port(5007)};
    LinuxCncController controller(options);
    CorrectionSettings settings;
    settings.conventions.diameterMode = false;
    settings.largestStepMm = 0.5;
    CorrectionWriter writer(settings);
    try {
        controller.connect();
        if (!bringUp(controller)) {
            state.SkipWithError("the test LinuxCNC is not ready (E-stop, power, homing)");
            return;
        }
        std::int64_t part = 1;
        for (auto _ : state) {
            const double d = 0.0001 * static_cast<double>(part % 7);
            const WriteRecord record =
                writer.write(controller, part++, {0.0123 + d, -0.0211 + d, 0.0157 - d, 0.0309 + d, -0.0087 - d});
            if (!record.applied()) {
                state.SkipWithError(record.message.c_str());
                return;
            }
        }
    } catch (const LinuxCncError& e) {
        state.SkipWithError(e.what());
        return;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LinuxCncWriteAndReadBackFiveCorrections)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
