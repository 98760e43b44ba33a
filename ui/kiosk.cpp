#include "ui/kiosk.h"

#include <QCoreApplication>
#include <QWidget>

#include "core/auth/permission.h"
#include "core/storage/data_stores.h"
#include "ui/app_context.h"
#include "ui/auth/login_dialog.h"
#include "ui/auth/user_session.h"
#include "ui/prompt.h"

namespace tt::ui {

bool engineerMayQuit(QWidget* parent, Prompt* prompt) {
    if (!prompt) return false;
    const QString title = QCoreApplication::translate("tt::ui::Kiosk", "Quit the terminal");
    const QString question = QCoreApplication::translate(
        "tt::ui::Kiosk",
        "This terminal runs in kiosk mode: only an engineer may quit it.\n\nAre you an engineer, and do you want "
        "to quit TrueTurn?");
    return prompt->ask(parent, title, question) == Prompt::Answer::Yes;
}

bool engineerMayQuit(AppContext& context, QWidget* parent) {
    constexpr auto kQuitting = core::auth::Permission::EditSettings;  // the engineer's and administrator's
    UserSession* session = context.session;
    if (!session || session->may(kQuitting)) return engineerMayQuit(parent, context.prompt);
    storage::UserStore* users = context.data().users();
    if (!users) return false;
    LoginDialog logIn(*users, *session, LoginDialog::Leave::Cancel, parent);
    return logIn.exec() == QDialog::Accepted && session->may(kQuitting);
}

void showAsKiosk(QWidget* window) {
    window->setWindowFlags(window->windowFlags() | Qt::FramelessWindowHint);
    window->showFullScreen();
}

}  // namespace tt::ui
