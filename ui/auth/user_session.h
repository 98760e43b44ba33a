#pragma once

#include <QObject>
#include <QString>
#include <cstdint>
#include <functional>
#include <optional>

#include "core/auth/access_guard.h"
#include "core/auth/idle_logout.h"

class QTimer;

namespace tt::ui {

class AppState;

/// Who is logged in at the terminal and for how long they may stay idle: owns the access guard the
/// stores ask (AppContext::access), watches the application's input (keys, clicks, touches) and
/// logs out after the idle time of the log-in policy. The clock can be replaced for tests.
class UserSession : public QObject {
    Q_OBJECT
public:
    /// `state` (may be null) shows the logged-in user's name as the operator's.
    explicit UserSession(AppState* state = nullptr, QObject* parent = nullptr);
    ~UserSession() override;

    /// The guard to give to the stores (AppContext::access).
    const core::auth::AccessGuard& guard() const { return m_guard; }
    /// Who is logged in, if anyone.
    const std::optional<core::auth::Identity>& identity() const { return m_guard.identity(); }
    /// Whether the logged-in user may do `permission`.
    bool may(core::auth::Permission permission) const { return m_guard.may(permission); }
    /// "Anna (administrator)"-style text in the user's language; "nobody" when logged out.
    QString describe() const;

    /// Logs `identity` in with the automatic log-out after `idleMinutes` (core::auth limits).
    void logIn(const core::auth::Identity& identity, int idleMinutes);
    /// Logs out (`idle`: because of the idle time); emits loggedOut when someone was logged in.
    void logOut(bool idle = false);

    /// Milliseconds of a monotonic clock (default: QElapsedTimer since the session was made).
    void setClock(std::function<std::int64_t()> clockMs);
    /// The user did something now.
    void touch();
    /// Logs out when the idle time has passed (the session's timer calls it every second).
    void checkIdle();

    /// Translated name of a role ("Engineer").
    static QString roleName(core::auth::Role role);

signals:
    void loggedIn();
    void loggedOut(bool idle);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    core::auth::AccessGuard m_guard;
    std::optional<core::auth::IdleLogout> m_idle;
    std::function<std::int64_t()> m_clockMs;
    AppState* m_state;
    QTimer* m_timer;
};

}  // namespace tt::ui
