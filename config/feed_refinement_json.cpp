#include "config/feed_refinement_json.h"

#include <QJsonArray>

namespace tt::config {

namespace {

QJsonArray numbers(const std::vector<double>& v) {
    QJsonArray a;
    for (double x : v)
        a.append(x);
    return a;
}

QJsonObject roundToJson(const core::FeedRefinementRound& r) {
    QJsonObject out{{QStringLiteral("round"), r.round},
                    {QStringLiteral("plan"), refinementProposalToJson(r.plan)},
                    {QStringLiteral("measurements"), r.measurements}};
    if (r.fit) {
        const core::LinearRegression& g = r.fit->regression;
        out.insert(QStringLiteral("model"),
                   QJsonObject{{QStringLiteral("term_set"),
                                QString::fromStdString(core::deformationTermSetName(r.fit->termSet))},
                               {QStringLiteral("terms"), g.termCount},
                               {QStringLiteral("n"), g.pointCount},
                               {QStringLiteral("r2"), g.r2},
                               {QStringLiteral("sigma_resid_um"), g.residualSigma},
                               {QStringLiteral("two_sigma_um"), r.fit->twoSigmaUm()}});
    }
    if (r.schedule) {
        out.insert(QStringLiteral("yc_um"), r.schedule->levelUm);
        out.insert(QStringLiteral("segments"), static_cast<int>(r.schedule->segments.size()));
        out.insert(QStringLiteral("model_deviation_pct"), r.schedule->modelDeviationPct());
    }
    if (r.check) out.insert(QStringLiteral("verify"), feedScheduleCheckToJson(*r.check));
    if (!r.problem.empty()) out.insert(QStringLiteral("problem"), QString::fromStdString(r.problem));
    return out;
}

}  // namespace

QJsonObject feedScheduleCheckToJson(const core::FeedScheduleCheck& check) {
    return {{QStringLiteral("max_deviation_pct"), check.maxDeviationPct},
            {QStringLiteral("worst_z"), check.worstZMm},
            {QStringLiteral("worst_y_um"), check.worstYUm},
            {QStringLiteral("within_10_pct"), check.maxDeviationPct <= core::kFeedScheduleTolerancePct},
            {QStringLiteral("fmax_excess_pct"), check.feedMaxExcessPct},
            {QStringLiteral("fmax_worst_z"), check.feedMaxWorstZMm},
            {QStringLiteral("fmin_shortfall_pct"), check.feedMinShortfallPct}};
}

QJsonObject refinementProposalToJson(const core::RefinementProposal& plan) {
    QJsonArray bars;
    for (const core::RefinementBar& b : plan.bars)
        bars.append(QJsonObject{{QStringLiteral("f"), b.feedMmPerRev}, {QStringLiteral("z"), numbers(b.zMm)}});
    return {{QStringLiteral("depth_mm"), plan.depthMm},
            {QStringLiteral("bars"), bars},
            {QStringLiteral("bar_count"), static_cast<int>(plan.bars.size())},
            {QStringLiteral("gauge_points"), plan.gaugePointCount()},
            {QStringLiteral("sigma_um"), plan.sigmaUm},
            {QStringLiteral("margin_um"), plan.marginUm},
            {QStringLiteral("target_half_width_um"), plan.targetHalfWidthUm},
            {QStringLiteral("half_width_before_um"), plan.halfWidthBeforeUm},
            {QStringLiteral("half_width_after_um"), plan.halfWidthAfterUm},
            {QStringLiteral("measurements_before"), plan.measurementsBefore},
            {QStringLiteral("feed_levels_before"), plan.feedLevelsBefore}};
}

QJsonObject feedRefinementToJson(const core::FeedRefinement& refinement, int maxRounds) {
    QJsonArray rounds;
    for (const core::FeedRefinementRound& r : refinement.rounds)
        rounds.append(roundToJson(r));
    const core::FeedScheduleCheck& initial = refinement.initialCheck;
    QJsonObject out{
        {QStringLiteral("rounds_run"), static_cast<int>(refinement.rounds.size())},
        {QStringLiteral("max_rounds"), maxRounds},
        {QStringLiteral("bars"), refinement.barCount()},
        {QStringLiteral("gauge_points"), refinement.gaugePointCount()},
        {QStringLiteral("within_10_pct"), refinement.withinTolerance()},
        {QStringLiteral("initial"),
         QJsonObject{{QStringLiteral("max_deviation_pct"), initial.maxDeviationPct},
                     {QStringLiteral("worst_z"), initial.worstZMm},
                     {QStringLiteral("within_10_pct"), initial.maxDeviationPct <= core::kFeedScheduleTolerancePct}}},
        {QStringLiteral("rounds"), rounds}};
    if (!refinement.advice.empty()) out.insert(QStringLiteral("advice"), QString::fromStdString(refinement.advice));
    return out;
}

DeformationModelFile refinedModelFile(const core::DeformationFit& fit, const DeformationModelFile& base, int bars) {
    DeformationModelFile file = deformationModelFile(fit);
    const QString from = base.sourceFile.isEmpty() ? QStringLiteral("the model") : base.sourceFile;
    file.sourceFile = QStringLiteral("%1 + %2 targeted bars at a = %3 mm")
                          .arg(from)
                          .arg(bars)
                          .arg(fit.model.coding(core::DeformationFactor::Depth).centre, 0, 'g', 6);
    file.preset = base.preset;
    file.seed = base.seed;
    file.job = base.job;
    return file;
}

}  // namespace tt::config
