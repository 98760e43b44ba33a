#include "app/cli/simulate_verdicts.h"

#include "config/json_eigen.h"

namespace tt::cli {

namespace {

QJsonObject countsJson(const core::VerdictCounts& c) {
    return {{QStringLiteral("good"), static_cast<qint64>(c.good)},
            {QStringLiteral("rework"), static_cast<qint64>(c.rework)},
            {QStringLiteral("scrap"), static_cast<qint64>(c.scrap)}};
}

}  // namespace

QJsonObject verdictsJson(const core::LatheStudyResult& r) {
    QJsonObject out = countsJson(r.verdicts);
    out.insert(QStringLiteral("machined_parts"), static_cast<qint64>(r.verdicts.total()));
    out.insert(QStringLiteral("warmup"), countsJson(r.warmupVerdicts));
    return out;
}

QString verdictsText(const core::LatheStudyResult& r) {
    return QStringLiteral(
               "verdicts of all %1 machined parts (warm-up included): %2 good, %3 rework, %4 scrap; of the %5 "
               "warm-up parts: %6 good, %7 rework, %8 scrap; %9 out-of-tolerance alarm(s)")
        .arg(r.verdicts.total())
        .arg(r.verdicts.good)
        .arg(r.verdicts.rework)
        .arg(r.verdicts.scrap)
        .arg(r.warmupParts)
        .arg(r.warmupVerdicts.good)
        .arg(r.warmupVerdicts.rework)
        .arg(r.warmupVerdicts.scrap)
        .arg(r.toleranceAlarms);
}

QJsonObject correctionsJson(const core::LatheStudyResult& r, const core::CorrectionLimits& limits) {
    return {{QStringLiteral("max_abs_mm"), r.maxCorrectionMm},
            {QStringLiteral("max_step_mm"), r.maxCorrectionStepMm},
            {QStringLiteral("limit_abs_mm"), config::limitOrNull(limits.maxAbsMm)},
            {QStringLiteral("limit_step_mm"), config::limitOrNull(limits.maxStepMm)}};
}

QJsonObject presetDump(const config::LoopScenario& scenario) {
    QJsonObject out = scenario.json;
    out.remove(QStringLiteral("based_on"));
    return out;
}

}  // namespace tt::cli
