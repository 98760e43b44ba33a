#include "ui/auth/log_in_gate.h"

#include <QObject>
#include <QWidget>

#include "ui/app_context.h"
#include "ui/auth/first_start_dialog.h"
#include "ui/auth/login_dialog.h"
#include "ui/auth/user_session.h"
#include "ui/log_categories.h"

namespace tt::ui {

bool logInAtStart(AppContext& context, QWidget* parent) {
    storage::UserStore* users = context.data().users();
    if (!users || !context.session) return true;
    if (!users->hasUsers()) {
        qCInfo(lcUi) << "first start: no user yet, asking for the administrator";
        FirstStartDialog dialog(*users, *context.session, parent);
        return dialog.exec() == QDialog::Accepted;
    }
    qCInfo(lcUi) << "asking for a log-in";
    LoginDialog dialog(*users, *context.session, LoginDialog::Leave::Quit, parent);
    const bool in = dialog.exec() == QDialog::Accepted;
    if (in) qCInfo(lcUi).noquote() << "logged in:" << context.session->describe();
    return in;
}

void logInAgainAfterLogOut(AppContext& context, QWidget* window) {
    if (!context.session) return;
    QObject::connect(context.session, &UserSession::loggedOut, window, [&context, window](bool) {
        storage::UserStore* users = context.data().users();
        if (!users) return;
        LoginDialog dialog(*users, *context.session, LoginDialog::Leave::Never, window);
        dialog.exec();
    });
}

}  // namespace tt::ui
