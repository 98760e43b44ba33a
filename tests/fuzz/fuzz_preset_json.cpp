// libFuzzer target: the preset readers of the config layer (Qt Core) on arbitrary bytes parsed as JSON:
// the run-to-run plant and controller (plant_config) when the first byte is even, the boring
// scenario (boring_config) otherwise. A refusal is an exception; a crash, a sanitizer report or a
// hang is a finding.
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstddef>
#include <cstdint>
#include <exception>

#include "config/boring_config.h"
#include "config/plant_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const QJsonDocument doc =
        QJsonDocument::fromJson(QByteArray(reinterpret_cast<const char*>(data + 1), static_cast<qsizetype>(size - 1)));
    if (!doc.isObject()) return 0;
    try {
        if (data[0] % 2 == 0)
            (void)tt::config::runToRunSetupFromPreset(doc.object(), std::nullopt);
        else
            (void)tt::config::boringScenarioFromPreset(doc.object());
    } catch (const std::exception&) {
    }
    return 0;
}
