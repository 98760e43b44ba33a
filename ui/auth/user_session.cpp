#include "ui/auth/user_session.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QTimer>
#include <memory>

#include "ui/app_state.h"

namespace tt::ui {

UserSession::UserSession(AppState* state, QObject* parent)
    : QObject(parent), m_state(state), m_timer(new QTimer(this)) {
    auto started = std::make_shared<QElapsedTimer>();
    started->start();
    m_clockMs = [started] { return static_cast<std::int64_t>(started->elapsed()); };
    m_timer->setInterval(1000);
    connect(m_timer, &QTimer::timeout, this, &UserSession::checkIdle);
    if (QCoreApplication::instance()) QCoreApplication::instance()->installEventFilter(this);
}

UserSession::~UserSession() {
    if (QCoreApplication::instance()) QCoreApplication::instance()->removeEventFilter(this);
}

QString UserSession::roleName(core::auth::Role role) {
    switch (role) {
        case core::auth::Role::Operator:
            return tr("Operator");
        case core::auth::Role::Engineer:
            return tr("Engineer");
        case core::auth::Role::Quality:
            return tr("Quality");
        case core::auth::Role::Administrator:
            return tr("Administrator");
    }
    return QString();
}

QString UserSession::describe() const {
    if (!identity()) return tr("nobody is logged in");
    return tr("%1 (%2)").arg(QString::fromStdString(identity()->name), roleName(identity()->role));
}

void UserSession::logIn(const core::auth::Identity& identity, int idleMinutes) {
    core::auth::IdleLogout idle(idleMinutes);  // throws out of limits before anything changes
    m_guard.logIn(identity);
    m_idle = idle;
    m_idle->touch(m_clockMs());
    m_timer->start();
    if (m_state) m_state->setOperatorName(QString::fromStdString(identity.name));
    emit loggedIn();
}

void UserSession::logOut(bool idle) {
    const bool wasIn = m_guard.identity().has_value();
    m_guard.logOut();
    m_idle.reset();
    m_timer->stop();
    if (m_state) m_state->setOperatorName(QString());
    if (wasIn) emit loggedOut(idle);
}

void UserSession::setClock(std::function<std::int64_t()> clockMs) {
    m_clockMs = std::move(clockMs);
    if (m_idle) m_idle->touch(m_clockMs());
}

void UserSession::touch() {
    if (m_idle) m_idle->touch(m_clockMs());
}

void UserSession::checkIdle() {
    if (m_idle && m_idle->expired(m_clockMs())) logOut(true);
}

bool UserSession::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
        case QEvent::KeyPress:
        case QEvent::MouseButtonPress:
        case QEvent::TouchBegin:
        case QEvent::Wheel:
            touch();
            break;
        default:
            break;
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace tt::ui
