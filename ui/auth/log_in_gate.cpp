#include "ui/auth/log_in_gate.h"

#include <QObject>
#include <QWidget>

#include "ui/app_context.h"
#include "ui/auth/first_start_dialog.h"
#include "ui/auth/login_dialog.h"
#include "ui/auth/user_session.h"

namespace tt::ui {

bool logInAtStart(AppContext& context, QWidget* parent) {
    storage::UserStore* users = context.data().users();
    if (!users || !context.session) return true;
    if (!users->hasUsers()) {
        FirstStartDialog dialog(*users, *context.session, parent);
        return dialog.exec() == QDialog::Accepted;
    }
    LoginDialog dialog(*users, *context.session, true, parent);
    return dialog.exec() == QDialog::Accepted;
}

void logInAgainAfterLogOut(AppContext& context, QWidget* window) {
    if (!context.session) return;
    QObject::connect(context.session, &UserSession::loggedOut, window, [&context, window](bool) {
        storage::UserStore* users = context.data().users();
        if (!users) return;
        LoginDialog dialog(*users, *context.session, false, window);
        dialog.exec();
    });
}

}  // namespace tt::ui
