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
    /// How the dialog may be left without logging in.
    enum class Leave {
        Never,   ///< it stays until someone logs in (after a log-out)
        Quit,    ///< a Quit button: at the start, leaving quits the application
        Cancel,  ///< a Cancel button: asked for someone else's log-in (the kiosk's engineer), back to the terminal
    };
    LoginDialog(storage::UserStore& users, UserSession& session, Leave leave, QWidget* parent = nullptr);

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
    /// Log in (the default button) and the Quit or Cancel button (object name "leaveButton").
    QHBoxLayout* buildButtons();
    QWidget* buildKeypad();

    storage::UserStore& m_users;
    UserSession& m_session;
    Leave m_leave;
    std::function<std::int64_t()> m_clockS;
    QComboBox* m_user;
    QLineEdit* m_secret;
    QLabel* m_message;
};

}  // namespace tt::ui
