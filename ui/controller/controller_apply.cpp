#include "ui/controller/controller_apply.h"

#include <QLoggingCategory>
#include <QStringList>

#include "ui/app_state.h"
#include "ui/log_categories.h"

namespace tt::ui {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 6);
}

void compare(QStringList& out, const QString& what, double before, double after) {
    if (before != after) out << QStringLiteral("%1 %2 -> %3").arg(what, number(before), number(after));
}

}  // namespace

QString describeTuningChange(const core::RunToRunSetup& before, const core::RunToRunSetup& after) {
    QStringList out;
    compare(out, QStringLiteral("delay z"), before.plant.delay, after.plant.delay);
    const Eigen::Index n = std::min(before.weights.R1.rows(), after.weights.R1.rows());
    for (Eigen::Index i = 0; i < n; ++i) {
        compare(out, QStringLiteral("point %1 R1").arg(i + 1), before.weights.R1(i, i), after.weights.R1(i, i));
        compare(out, QStringLiteral("point %1 R2").arg(i + 1), before.weights.R2(i, i), after.weights.R2(i, i));
    }
    compare(out, QStringLiteral("max correction mm"), before.limits.maxAbsMm, after.limits.maxAbsMm);
    compare(out, QStringLiteral("max step mm"), before.limits.maxStepMm, after.limits.maxStepMm);
    compare(out, QStringLiteral("dead band mm"), before.ewma.deadBandMm, after.ewma.deadBandMm);
    const std::string da = before.plant.points.empty() ? std::string() : before.plant.points[0].disturbance.describe();
    const std::string db = after.plant.points.empty() ? std::string() : after.plant.points[0].disturbance.describe();
    if (da != db)
        out << QStringLiteral("shaping filter %1 -> %2").arg(QString::fromStdString(da), QString::fromStdString(db));
    return out.join(QStringLiteral("; "));
}

QString recordTuningChange(AppContext& context, const core::RunToRunSetup& before, const core::RunToRunSetup& after) {
    const QString who = context.state ? context.state->operatorName() : QString();
    const QString record =
        QStringLiteral("controller tuning applied by %1: %2")
            .arg(who.isEmpty() ? QStringLiteral("(no operator)") : who, describeTuningChange(before, after));
    qCInfo(lcLoop).noquote() << record;
    return record;
}

}  // namespace tt::ui
