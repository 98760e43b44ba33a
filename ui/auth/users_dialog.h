#pragma once

#include <QDialog>
#include <functional>

class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;
class QVBoxLayout;

namespace tt::storage {
class UserStore;
}

namespace tt::ui {

/// The administrator's users management: the users with role and lock-out, adding one, changing a
/// role, setting a new password or PIN, unlocking, removing; the log-in policies (failed log-ins
/// before the lock-out, its duration, the idle log-out). The store refuses whoever may not
/// (core::auth::Permission::ManageUsers); the refusal is shown.
class UsersDialog : public QDialog {
    Q_OBJECT
public:
    explicit UsersDialog(storage::UserStore& users, QWidget* parent = nullptr);

    void reload();
    /// Adds the user of the form fields; true when added.
    bool addUser();
    /// Gives the selected user the role of the form.
    bool setRole();
    /// Sets the form's password or PIN for the selected user.
    bool setSecret();
    bool unlock();
    bool removeUser();
    /// Stores the log-in policies of the spin boxes.
    bool applyPolicy();

    QTableWidget* table() const { return m_table; }
    QLineEdit* nameEdit() const { return m_name; }
    QComboBox* roleCombo() const { return m_role; }
    QComboBox* kindCombo() const { return m_kind; }
    QLineEdit* secretEdit() const { return m_secret; }
    QSpinBox* idleMinutes() const { return m_idle; }
    QString statusText() const;

private:
    /// The users: name, role, how they log in, locked or not.
    void setUpTable();
    /// Limits, choices and units of the user's fields and the log-in rules.
    void setUpFields();
    /// The table with the side column beside it, the status and Close below.
    void buildLayout();
    /// The user's fields, the actions on the selected user and the log-in rules.
    QVBoxLayout* buildSide();
    /// Add, Set role, Set PIN or password, Unlock, Remove in two columns.
    QGridLayout* buildUserActions();
    QString selectedName() const;
    bool run(const QString& done, const std::function<void()>& work);

    storage::UserStore& m_users;
    QTableWidget* m_table;
    QLineEdit* m_name;
    QComboBox* m_role;
    QComboBox* m_kind;
    QLineEdit* m_secret;
    QSpinBox* m_failures;
    QSpinBox* m_lockMinutes;
    QSpinBox* m_idle;
    QLabel* m_status;
};

}  // namespace tt::ui
