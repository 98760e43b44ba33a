#include "ui/run/interrupted_run.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <stdexcept>

#include "core/storage/data_stores.h"
#include "ui/app_context.h"
#include "ui/log_categories.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"
#include "ui/prompt.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {

namespace {

/// The built-in simulator's lathe (devices/builtin), the machine an interrupted run continues on.
const QString kBuiltInLatheKey = QStringLiteral("simulated-lathe");

}  // namespace

core::RunDescription storedRunDescription(const RunSettings& settings, const core::ShaftRunPlan& plan) {
    QJsonObject json{
        {QStringLiteral("source"), QStringLiteral("gui")},
        {QStringLiteral("preset"), settings.preset},
        {QStringLiteral("controller"), settings.controller},
        {QStringLiteral("delay"), plan.loop.delayParts},
        {QStringLiteral("seed"), QString::number(settings.seed)},
        {QStringLiteral("ewma_weight"), plan.ewmaWeight},
        {QStringLiteral("machine"), settings.operatorCycle ? QStringLiteral("real-lathe") : settings.machineKey}};
    if (settings.operatorCycle) {
        json.insert(QStringLiteral("cnc_output"), settings.outputName);
        json.insert(QStringLiteral("gauge"),
                    settings.gaugeName.isEmpty() ? QStringLiteral("by hand") : settings.gaugeName);
    }
    if (plan.loop.lastPartNumber)
        json.insert(QStringLiteral("last_part"), static_cast<qint64>(*plan.loop.lastPartNumber));
    return {settings.preset.toStdString(),
            settings.controller.toStdString(),
            plan.loop.delayParts,
            plan.loop.nominalDiameterMm,
            plan.loop.partLengthMm,
            plan.loop.pointZMm,
            QJsonDocument(json).toJson(QJsonDocument::Compact).toStdString()};
}

RunSettings settingsOfStoredRun(const core::RunSummary& run) {
    const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(run.description.settingsJson)).object();
    const QString source = o.value(QStringLiteral("source")).toString();
    RunSettings s;
    s.machineKey = kBuiltInLatheKey;
    s.preset = o.value(QStringLiteral("preset")).toString();
    s.controller = o.value(QStringLiteral("controller")).toString();
    s.delay = o.value(QStringLiteral("delay")).toInt();
    if (const QJsonValue w = o.value(QStringLiteral("ewma_weight")); w.isDouble()) s.ewmaWeight = w.toDouble();
    if (source == QLatin1String("gui")) {
        if (o.value(QStringLiteral("machine")).toString() != kBuiltInLatheKey)
            throw std::invalid_argument("run " + std::to_string(run.runId) +
                                        " was not made on the simulated lathe; it continues only there");
        s.seed = o.value(QStringLiteral("seed")).toString().toULongLong();
        if (o.contains(QStringLiteral("last_part")))
            s.lastPartNumber = o.value(QStringLiteral("last_part")).toInteger();
    } else if (source == QLatin1String("simulate")) {
        s.seed = static_cast<std::uint64_t>(o.value(QStringLiteral("seed")).toInteger());
        s.lastPartNumber = o.value(QStringLiteral("warmup")).toInteger() + o.value(QStringLiteral("parts")).toInteger();
    } else {
        throw std::invalid_argument("run " + std::to_string(run.runId) + " was not started on this terminal");
    }
    if (s.preset.isEmpty() || s.delay < 1 || s.delay > core::kMaxDelay || (s.lastPartNumber && *s.lastPartNumber < 1))
        throw std::invalid_argument("the settings stored with run " + std::to_string(run.runId) + " are damaged");
    core::controllerKindFromName(s.controller.toStdString());  // throws for an unknown controller
    return s;
}

std::optional<InterruptedRun> findInterruptedRun(AppContext& context) {
    try {
        core::HistoryStore* history = context.data().history();
        if (!history) return std::nullopt;
        const std::vector<core::RunSummary> runs = history->runs();
        if (runs.empty() || runs.front().status != "running") return std::nullopt;
        std::optional<core::ResumePoint> point = history->resumePoint(runs.front().runId);
        if (!point) return std::nullopt;
        RunSettings settings = settingsOfStoredRun(point->run);
        settings.databasePath = context.databasePath;
        return InterruptedRun{std::move(*point), std::move(settings)};
    } catch (const std::exception& e) {
        qCWarning(lcUi).noquote() << "the interrupted run cannot be offered:" << e.what();
        return std::nullopt;
    }
}

bool offerInterruptedRun(AppContext& context, MainWindow& window) {
    if (!context.prompt) return false;
    const std::optional<InterruptedRun> run = findInterruptedRun(context);
    if (!run) return false;
    const core::RunSummary& summary = run->point.run;
    const QString planned = run->settings.lastPartNumber
                                ? QString::number(*run->settings.lastPartNumber)
                                : QCoreApplication::translate("tt::ui::InterruptedRun", "no end");
    const QString question =
        QCoreApplication::translate("tt::ui::InterruptedRun",
                                    "Run %1 (%2, %3, %4 of %5 parts done) was interrupted. Continue it from part %6?")
            .arg(summary.runId)
            .arg(summary.description.machine.empty()
                     ? QCoreApplication::translate("tt::ui::InterruptedRun", "simulated lathe")
                     : QString::fromStdString(summary.description.machine),
                 run->settings.preset)
            .arg(summary.partCount)
            .arg(planned)
            .arg(run->nextPart());
    if (context.prompt->ask(&window, QCoreApplication::translate("tt::ui::InterruptedRun", "Interrupted run"),
                            question) != Prompt::Answer::Yes)
        return false;
    window.showPage(PageId::Run);
    auto* page = qobject_cast<RunPage*>(window.page(PageId::Run));
    if (!page) return false;
    return page->shaft().resumeRun(*run);
}

}  // namespace tt::ui
