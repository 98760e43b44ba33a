// libFuzzer target: the preset and file readers of the config layer (Qt Core) not covered by
// fuzz_preset_json, on arbitrary bytes parsed as JSON; the first byte picks the reader:
//   0 the corrective-pulse preset (corner), 1 the corrective network file (corner --net),
//   2 the deformation model file (schedule-feed --model), 3 the feed-scheduling preset and its job,
//   4 the hydraulic feed preset (feed-stabilise), 5 the lathe section and station timing of a
//   shaft preset, 6 the systematic model of a preset (fit-profile --compare, simulate).
// A refusal is an exception; a crash, a sanitizer report or a hang is a finding.
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstddef>
#include <cstdint>
#include <exception>

#include "config/corner_config.h"
#include "config/corrective_net_json.h"
#include "config/deformation_model_config.h"
#include "config/feed_schedule_config.h"
#include "config/hydraulic_feed_config.h"
#include "config/lathe_config.h"
#include "config/profile_model_config.h"

namespace {

void readSection(std::uint8_t which, const QByteArray& bytes, const QJsonObject& json) {
    using namespace tt::config;
    switch (which % 7) {
        case 0:
            (void)cornerScenarioFromPreset(json);
            break;
        case 1:
            (void)cornerNetFromBytes(bytes);
            break;
        case 2:
            (void)deformationModelFromJson(json);
            break;
        case 3:
            (void)feedSchedulingSetupFromPreset(json);
            (void)feedPassJobFromPreset(json);
            break;
        case 4:
            (void)hydraulicFeedScenarioFromPreset(json);
            break;
        case 5:
            (void)latheSetupFromJson(json.value(QStringLiteral("lathe")).toObject());
            (void)stationTimingFromJson(json.value(QStringLiteral("lathe")).toObject());
            break;
        default:
            (void)systematicModelFromPreset(json);
            break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const QByteArray bytes(reinterpret_cast<const char*>(data + 1), static_cast<qsizetype>(size - 1));
    const QJsonDocument doc = QJsonDocument::fromJson(bytes);
    if (!doc.isObject() && data[0] % 7 != 1) return 0;
    try {
        readSection(data[0], bytes, doc.object());
    } catch (const std::exception&) {
    }
    return 0;
}
