#include "ui/history_check.h"

#include <QCoreApplication>
#include <exception>

#include <stdexcept>
#include "ui/app_context.h"
#include "ui/app_state.h"
#include "ui/prompt.h"

namespace tt::ui {

bool checkHistoryAtStart(AppContext& context, QWidget* parent, Prompt* prompt) {
    try {
        storage::Database* database = context.data().database();
        if (!database) throw std::runtime_error(context.data().problem().toStdString());
        if (context.state) context.state->setDatabaseDescription(database->config().describe());
        return true;
    } catch (const std::exception& e) {
        const QString reason = QString::fromStdString(e.what());
        if (context.state)
            context.state->setDatabaseDescription(
                QCoreApplication::translate("tt::ui::HistoryCheck", "not available — %1").arg(reason));
        if (prompt)
            prompt->warn(parent, QCoreApplication::translate("tt::ui::HistoryCheck", "Run history"),
                         QCoreApplication::translate("tt::ui::HistoryCheck",
                                                     "The run history cannot be used: %1\n\nRuns are not recorded "
                                                     "until this is fixed (Settings shows where the history is kept).")
                             .arg(reason));
        return false;
    }
}

}  // namespace tt::ui
