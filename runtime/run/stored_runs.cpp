#include "runtime/run/stored_runs.h"

#include <QJsonDocument>
#include <QJsonObject>

#include "runtime/run/machine_catalog.h"

namespace tt::runtime {

namespace {

const QString kSource = QStringLiteral("source");

/// A run of the Run page before the request format: preset, controller, delay, seed, EWMA weight, machine and
/// the last part.
RunRequest fromGuiSettings(const QJsonObject& o) {
    RunRequest q;
    q.machine = currentMachineKey(o.value(QStringLiteral("machine")).toString());
    q.preset = o.value(QStringLiteral("preset")).toString();
    q.delay = o.value(QStringLiteral("delay")).toInt();
    q.controller = core::controllerKindFromName(o.value(QStringLiteral("controller")).toString().toStdString());
    if (const QJsonValue w = o.value(QStringLiteral("ewma_weight"));
        w.isDouble() && q.controller != core::ControllerKind::Lqg && q.controller != core::ControllerKind::Open)
        q.ewmaWeight = w.toDouble();
    q.seed = o.value(QStringLiteral("seed")).toString().toULongLong();
    if (o.contains(QStringLiteral("last_part"))) q.endPart = o.value(QStringLiteral("last_part")).toInteger();
    return q;
}

/// A run of `trueturn simulate --db` before the request format: its warm-up plus parts are its last part.
RunRequest fromSimulateSettings(const QJsonObject& o) {
    RunRequest q;
    q.preset = o.value(QStringLiteral("preset")).toString();
    q.delay = o.value(QStringLiteral("delay")).toInt();
    q.controller = core::controllerKindFromName(o.value(QStringLiteral("controller")).toString().toStdString());
    const QJsonValue w = o.value(QStringLiteral("ewma_weight"));
    if (w.isDouble()) q.ewmaWeight = w.toDouble();
    q.ewmaAuto = w.isString();
    q.seed = static_cast<std::uint64_t>(o.value(QStringLiteral("seed")).toInteger());
    q.warmupParts = o.value(QStringLiteral("warmup")).toInteger();
    q.endPart = q.warmupParts + o.value(QStringLiteral("parts")).toInteger();
    return q;
}

}  // namespace

core::RunDescription storedRunDescription(const RunRequest& request, const core::ShaftRunPlan& plan) {
    QJsonObject stored = toJson(request);
    stored.remove(QStringLiteral("database"));
    const QJsonObject settings{{kSource, QStringLiteral("request")}, {QStringLiteral("request"), stored}};
    core::RunDescription d{request.preset.toStdString(),
                           core::controllerKindName(request.controller),
                           plan.loop.delayParts,
                           plan.loop.nominalDiameterMm,
                           plan.loop.partLengthMm,
                           plan.loop.pointZMm,
                           QJsonDocument(settings).toJson(QJsonDocument::Compact).toStdString()};
    d.machine = request.lathe.toStdString();
    return d;
}

RunRequest requestOfStoredRun(const core::RunSummary& run) {
    const std::string which = "run " + std::to_string(run.runId);
    const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(run.description.settingsJson)).object();
    const QString source = o.value(kSource).toString();
    RunRequest q;
    try {
        if (source == QLatin1String("request"))
            q = runRequestFromJson(o.value(QStringLiteral("request")).toObject());
        else if (source == QLatin1String("gui"))
            q = fromGuiSettings(o);
        else if (source == QLatin1String("simulate"))
            q = fromSimulateSettings(o);
        else
            throw RunRequestError("source", "the run was not started by TrueTurn's Run page or 'trueturn simulate'");
        validate(q);
    } catch (const RunRequestError& e) {
        throw RunRequestError(e.field,
                              std::string("the settings stored with ") + which + " cannot be used: " + e.what());
    } catch (const std::invalid_argument& e) {
        throw RunRequestError("source", "the settings stored with " + which + " are damaged: " + e.what());
    }
    return q;
}

std::optional<InterruptedRun> findInterruptedRun(core::HistoryStore& history) {
    const std::vector<core::RunSummary> runs = history.runs();
    if (runs.empty() || runs.front().status != "running") return std::nullopt;
    std::optional<core::ResumePoint> point = history.resumePoint(runs.front().runId);
    if (!point) return std::nullopt;
    RunRequest request = requestOfStoredRun(point->run);
    return InterruptedRun{std::move(*point), std::move(request)};
}

}  // namespace tt::runtime
