// The adaptive loop on the command line: `simulate`'s --mismatch-action and --dither-share, and the adaptations
// in its output. The adaptation itself is core::AdaptiveLoop, run by the loop engine.
#include "app/cli/simulate_adaptation.h"

#include <QJsonArray>
#include <QString>

#include "app/cli/command.h"
#include "core/loop/mismatch_monitor.h"
#include "core/storage/adaptation_json.h"

namespace tt::cli {

void addAdaptationJson(QJsonObject& out, const core::LatheStudyResult& r, const config::LoopScenario& scenario) {
    out.insert(QStringLiteral("mismatch_action"),
               QString::fromLatin1(core::mismatchActionName(scenario.mismatchMonitor.action)));
    QJsonArray adaptations;
    for (const core::AdaptationRecord& a : r.adaptations)
        adaptations.append(storage::adaptationJson(a));
    out.insert(QStringLiteral("adaptations"), adaptations);
    QJsonArray notices;
    for (const core::RecordedAlarm& n : r.adaptationNotices)
        notices.append(
            QJsonObject{{QStringLiteral("part"), static_cast<qint64>(n.part)},
                        {QStringLiteral("kind"), QString::fromStdString(core::noticeKindName(n.notice.kind))},
                        {QStringLiteral("message"), QString::fromStdString(core::describe(n.notice))}});
    out.insert(QStringLiteral("adaptation_notices"), notices);
    QJsonObject corrections = out.value(QStringLiteral("corrections")).toObject();
    corrections.insert(QStringLiteral("max_switch_step_mm"), r.maxSwitchStepMm);
    corrections.insert(QStringLiteral("switches"), r.switches);
    out.insert(QStringLiteral("corrections"), corrections);
}

void printAdaptationText(const core::LatheStudyResult& r) {
    for (const core::RecordedAlarm& n : r.adaptationNotices)
        printLine(QStringLiteral("adaptation: ") + QString::fromStdString(core::describe(n.notice)));
    if (r.switches > 0)
        printLine(QStringLiteral("%1 controller switch(es); largest correction step around them %2 mm")
                      .arg(r.switches)
                      .arg(r.maxSwitchStepMm, 0, 'f', 4));
}

}  // namespace tt::cli
