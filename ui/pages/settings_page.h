#pragma once

#include "ui/page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tt::ui {

/// Operator and terminal settings: interface language, the operator's name (recorded with every
/// change the operator applies; the logged-in user when there is a session), where the run history is
/// stored; who is logged in, log out, the users (administrator) and the audit trail.
class SettingsPage : public Page {
    Q_OBJECT
public:
    explicit SettingsPage(AppContext& context, QWidget* parent = nullptr);
    QString title() const override;
    void retranslate() override;

private:
    /// The general section (language, operator, database) and the users section (who is logged in,
    /// log out, users, audit trail).
    void buildLayout();
    void fillLanguages();
    void onLanguageChosen(int index);
    void onOperatorEdited();
    /// The logged-in user, what they may open, the operator field following the session.
    void showSession();
    void openUsers();
    void openAudit();

    QLabel* m_languageLabel;
    QComboBox* m_language;
    QLabel* m_operatorLabel;
    QLineEdit* m_operator;
    QLabel* m_databaseLabel;
    QLabel* m_database;
    QLabel* m_machineLabel;
    QLabel* m_machine;  ///< this lathe's name in a plant database (shown with a plant database only)
    QLabel* m_sectionGeneral;
    QLabel* m_sectionUsers;
    QLabel* m_userLabel;
    QLabel* m_user;
    QPushButton* m_logOut;
    QPushButton* m_users;
    QPushButton* m_audit;
};

}  // namespace tt::ui
