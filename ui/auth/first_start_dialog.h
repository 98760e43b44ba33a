#pragma once

#include <QDialog>

class QLabel;
class QLineEdit;
class QPushButton;

namespace tt::storage {
class UserStore;
}

namespace tt::ui {

class UserSession;

/// The first start (no user in the database): asks for the administrator's name and password
/// (twice), creates the administrator and logs them in. Quit leaves the application.
class FirstStartDialog : public QDialog {
    Q_OBJECT
public:
    FirstStartDialog(storage::UserStore& users, UserSession& session, QWidget* parent = nullptr);

    /// Creates the administrator from the fields (what the Create button does); on a problem shows it
    /// and returns false, nothing stored.
    bool create();
    /// The problem shown, empty when none.
    QString problemText() const;

    QLineEdit* nameEdit() const { return m_name; }
    QLineEdit* passwordEdit() const { return m_password; }
    QLineEdit* repeatEdit() const { return m_repeat; }

private:
    void showProblem(const QString& text);

    storage::UserStore& m_users;
    UserSession& m_session;
    QLineEdit* m_name;
    QLineEdit* m_password;
    QLineEdit* m_repeat;
    QLabel* m_problem;
};

}  // namespace tt::ui
