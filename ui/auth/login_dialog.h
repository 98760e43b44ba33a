#pragma once

#include <QDialog>
#include <cstdint>
#include <functional>

class QComboBox;
class QHBoxLayout;
class QLabel;
class QLineEdit;

namespace tt::storage {
class UserStore;
}

namespace tt::ui {

class UserSession;

/// The log-in: the user's name, the password or PIN (typed, or on large keys for gloved hands), the
/// failed attempts left and the lock-out in plain words. Quit only at the start of the application.
class LoginDialog : public QDialog {
    Q_OBJECT
public:
    /// `allowQuit`: offer Quit (at the start); otherwise the dialog stays until someone logs in.
    LoginDialog(storage::UserStore& users, UserSession& session, bool allowQuit, QWidget* parent = nullptr);

    /// Unix seconds for the lock-out (default: the system clock); replaced by tests.
    void setClock(std::function<std::int64_t()> unixS) { m_clockS = std::move(unixS); }
    /// Tries the name and secret of the fields (what the Log in button does); true when logged in.
    bool attempt();
    /// The message shown (wrong password, lock-out), empty when none.
    QString messageText() const;

    QComboBox* userCombo() const { return m_user; }
    QLineEdit* secretEdit() const { return m_secret; }

    void reject() override;

private:
    /// The title, the user and secret fields, the message, the buttons and the keypad.
    void buildLayout();
    /// Log in (the default button) and, at the start, Quit.
    QHBoxLayout* buildButtons();
    QWidget* buildKeypad();

    storage::UserStore& m_users;
    UserSession& m_session;
    bool m_allowQuit;
    std::function<std::int64_t()> m_clockS;
    QComboBox* m_user;
    QLineEdit* m_secret;
    QLabel* m_message;
};

}  // namespace tt::ui
