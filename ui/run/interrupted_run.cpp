#include "ui/run/interrupted_run.h"

#include <QCoreApplication>
#include <stdexcept>

#include "core/storage/data_stores.h"
#include "runtime/history/terminal_history.h"
#include "runtime/run/machine_catalog.h"
#include "ui/app_context.h"
#include "ui/log_categories.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"
#include "ui/prompt.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {

namespace {

/// The machine of the run in words: the lathe's name in the history, else the offer's name.
QString machineOf(AppContext& context, const runtime::InterruptedRun& run) {
    if (!run.point.run.description.machine.empty()) return QString::fromStdString(run.point.run.description.machine);
    if (const auto offer = runtime::MachineCatalog(context.devices).find(run.request.machine)) return offer->name;
    return run.request.machine;
}

}  // namespace

std::optional<runtime::InterruptedRun> findInterruptedRun(AppContext& context) {
    try {
        if (runtime::isPlantDatabase(context.databasePath)) {
            // The runs this terminal may continue are in its journal (their numbers are the journal's): the
            // plant database holds every machine's and may be unreachable now.
            runtime::TerminalHistoryOptions options;
            options.location = context.databasePath;
            options.machine = runtime::terminalMachineName();
            runtime::TerminalHistory local(options);
            return runtime::findInterruptedRun(local.store());
        }
        core::HistoryStore* history = context.data().history();
        return history ? runtime::findInterruptedRun(*history) : std::nullopt;
    } catch (const std::exception& e) {
        qCWarning(lcUi).noquote() << "the interrupted run cannot be offered:" << e.what();
        return std::nullopt;
    }
}

bool offerInterruptedRun(AppContext& context, MainWindow& window) {
    if (!context.prompt) return false;
    const std::optional<runtime::InterruptedRun> run = findInterruptedRun(context);
    if (!run) return false;
    const core::RunSummary& summary = run->point.run;
    const QString planned = run->request.endPart ? QString::number(*run->request.endPart)
                                                 : QCoreApplication::translate("tt::ui::InterruptedRun", "no end");
    const QString question =
        QCoreApplication::translate("tt::ui::InterruptedRun",
                                    "Run %1 (%2, %3, %4 of %5 parts done) was interrupted. Continue it from part %6?")
            .arg(summary.runId)
            .arg(machineOf(context, *run), run->request.preset)
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
