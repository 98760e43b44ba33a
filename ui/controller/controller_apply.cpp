#include "ui/controller/controller_apply.h"

#include <QList>
#include <QLoggingCategory>
#include <QPair>
#include <QStringList>
#include <QVariantMap>

#include "ui/app_state.h"
#include "ui/auth/audit_trail.h"
#include "ui/log_categories.h"

namespace tt::ui {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 6);
}

/// The controller's identified model in words ("none": the preset's plant is the model).
QString modelText(const core::RunToRunSetup& setup) {
    if (!setup.model) return QStringLiteral("none");
    QStringList gains;
    for (double g : setup.model->gain)
        gains << number(g);
    QStringList disturbances;
    for (const core::DisturbanceModel& d : setup.model->disturbance)
        disturbances << QString::fromStdString(d.describe());
    return QStringLiteral("plant delay z + %1; gains %2; disturbances %3; from %4")
        .arg(setup.model->lagParts)
        .arg(gains.join(QStringLiteral(", ")), disturbances.join(QStringLiteral(" | ")),
             QString::fromStdString(setup.model->source));
}

/// The tuning as named values, in the order they are described ("delay z", "point 1 R1", ...).
QList<QPair<QString, QString>> tuningValues(const core::RunToRunSetup& setup, Eigen::Index points) {
    QList<QPair<QString, QString>> values;
    values.append({QStringLiteral("delay z"), number(setup.plant.delay)});
    for (Eigen::Index i = 0; i < points; ++i) {
        values.append({QStringLiteral("point %1 R1").arg(i + 1), number(setup.weights.R1(i, i))});
        values.append({QStringLiteral("point %1 R2").arg(i + 1), number(setup.weights.R2(i, i))});
    }
    values.append({QStringLiteral("max correction mm"), number(setup.limits.maxAbsMm)});
    values.append({QStringLiteral("max step mm"), number(setup.limits.maxStepMm)});
    values.append({QStringLiteral("dead band mm"), number(setup.ewma.deadBandMm)});
    values.append(
        {QStringLiteral("integral action"), setup.integral.enabled ? QStringLiteral("on") : QStringLiteral("off")});
    values.append({QStringLiteral("integral weight"), number(setup.integral.weight)});
    const std::string filter =
        setup.plant.points.empty() ? std::string() : setup.plant.points[0].disturbance.describe();
    values.append({QStringLiteral("shaping filter"), QString::fromStdString(filter)});
    values.append({QStringLiteral("identified model"), modelText(setup)});
    return values;
}

/// The values that differ between two setups: name, before, after.
struct TuningChange {
    QString name;
    QString before;
    QString after;
};

QList<TuningChange> tuningChanges(const core::RunToRunSetup& before, const core::RunToRunSetup& after) {
    const Eigen::Index points = std::min(before.weights.R1.rows(), after.weights.R1.rows());
    const auto b = tuningValues(before, points);
    const auto a = tuningValues(after, points);
    QList<TuningChange> changes;
    for (qsizetype i = 0; i < b.size(); ++i)
        if (b[i].second != a[i].second) changes.append({b[i].first, b[i].second, a[i].second});
    return changes;
}

}  // namespace

QString describeTuningChange(const core::RunToRunSetup& before, const core::RunToRunSetup& after) {
    QStringList out;
    for (const TuningChange& change : tuningChanges(before, after))
        out << QStringLiteral("%1 %2 -> %3").arg(change.name, change.before, change.after);
    return out.join(QStringLiteral("; "));
}

QString recordTuningChange(AppContext& context, const core::RunToRunSetup& before, const core::RunToRunSetup& after) {
    QVariantMap valuesBefore;
    QVariantMap valuesAfter;
    for (const TuningChange& change : tuningChanges(before, after)) {
        valuesBefore.insert(change.name, change.before);
        valuesAfter.insert(change.name, change.after);
    }
    AuditTrail(context).recordValues(storage::audit_category::kController, QStringLiteral("controller"), valuesBefore,
                                     valuesAfter);
    const QString who = context.state ? context.state->operatorName() : QString();
    const QString record =
        QStringLiteral("controller tuning applied by %1: %2")
            .arg(who.isEmpty() ? QStringLiteral("(no operator)") : who, describeTuningChange(before, after));
    qCInfo(lcUi).noquote() << record;
    return record;
}

}  // namespace tt::ui
