#include "ui/pages/settings_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

#include "runtime/history/terminal_history.h"
#include "ui/app_state.h"
#include "ui/auth/audit_dialog.h"
#include "ui/auth/audit_trail.h"
#include "ui/auth/user_session.h"
#include "ui/auth/users_dialog.h"
#include "ui/language.h"
#include "ui/pages/planned_page.h"

namespace tt::ui {

namespace {
const QString kOperatorKey = QStringLiteral("operator/name");
}

SettingsPage::SettingsPage(AppContext& context, QWidget* parent)
    : Page(PageId::Settings, context, parent),
      m_languageLabel(new QLabel(this)),
      m_language(new QComboBox(this)),
      m_operatorLabel(new QLabel(this)),
      m_operator(new QLineEdit(this)),
      m_databaseLabel(new QLabel(this)),
      m_database(new QLabel(this)),
      m_machineLabel(new QLabel(this)),
      m_machine(new QLabel(this)),
      m_sectionGeneral(new QLabel(this)),
      m_sectionUsers(new QLabel(this)),
      m_userLabel(new QLabel(this)),
      m_user(new QLabel(this)),
      m_logOut(new QPushButton(this)),
      m_users(new QPushButton(this)),
      m_audit(new QPushButton(this)) {
    buildLayout();
    fillLanguages();
    const QString savedOperator = QSettings().value(kOperatorKey).toString();
    m_operator->setText(savedOperator);
    if (context.state && !context.session) context.state->setOperatorName(savedOperator);
    m_database->setText(context.databasePath);
    m_machine->setText(runtime::terminalMachineName());
    m_machine->setObjectName(QStringLiteral("plantMachine"));
    m_machineLabel->setVisible(runtime::isPlantDatabase(context.databasePath));
    m_machine->setVisible(runtime::isPlantDatabase(context.databasePath));

    connect(m_language, &QComboBox::activated, this, &SettingsPage::onLanguageChosen);
    connect(m_operator, &QLineEdit::editingFinished, this, &SettingsPage::onOperatorEdited);
    connect(m_users, &QPushButton::clicked, this, &SettingsPage::openUsers);
    connect(m_audit, &QPushButton::clicked, this, &SettingsPage::openAudit);
    if (context.session) {
        connect(m_logOut, &QPushButton::clicked, context.session, [s = context.session] { s->logOut(); });
        connect(context.session, &UserSession::loggedIn, this, &SettingsPage::showSession);
        connect(context.session, &UserSession::loggedOut, this, &SettingsPage::showSession);
    }
    retranslate();
}

void SettingsPage::buildLayout() {
    m_sectionGeneral->setObjectName(QStringLiteral("SectionTitle"));
    m_sectionUsers->setObjectName(QStringLiteral("SectionTitle"));
    m_user->setObjectName(QStringLiteral("sessionUser"));
    m_logOut->setObjectName(QStringLiteral("logOutButton"));
    m_users->setObjectName(QStringLiteral("usersButton"));
    m_audit->setObjectName(QStringLiteral("auditButton"));
    m_language->setObjectName(QStringLiteral("languageCombo"));
    m_operator->setObjectName(QStringLiteral("operatorEdit"));
    m_operator->setMaxLength(64);
    m_database->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_database->setWordWrap(true);

    auto* form = new QFormLayout;
    form->setVerticalSpacing(16);
    form->addRow(m_languageLabel, m_language);
    form->addRow(m_operatorLabel, m_operator);
    form->addRow(m_databaseLabel, m_database);
    form->addRow(m_machineLabel, m_machine);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(32, 24, 32, 24);
    layout->addWidget(m_sectionGeneral);
    layout->addLayout(form);
    layout->addSpacing(16);
    layout->addWidget(m_sectionUsers);
    auto* userRow = new QHBoxLayout;
    userRow->setSpacing(12);
    userRow->addWidget(m_userLabel);
    userRow->addWidget(m_user, 1);
    userRow->addWidget(m_logOut);
    userRow->addWidget(m_users);
    userRow->addWidget(m_audit);
    layout->addLayout(userRow);
    layout->addStretch(1);
}

QString SettingsPage::title() const {
    return pageTitle(PageId::Settings);
}

void SettingsPage::fillLanguages() {
    for (const QString& code : LanguageSwitcher::available())
        m_language->addItem(LanguageSwitcher::nativeName(code), code);
    if (context().language) m_language->setCurrentIndex(m_language->findData(context().language->current()));
}

void SettingsPage::onLanguageChosen(int index) {
    if (!context().language) return;
    const QString before = context().language->current();
    const QString after = m_language->itemData(index).toString();
    if (before == after) return;
    context().language->apply(after);
    AuditTrail(context()).recordValues(QStringLiteral("setting"), QStringLiteral("terminal"),
                                       {{QStringLiteral("language"), before}}, {{QStringLiteral("language"), after}});
}

void SettingsPage::onOperatorEdited() {
    const QString name = m_operator->text().trimmed();
    QSettings().setValue(kOperatorKey, name);
    if (context().state) context().state->setOperatorName(name);
}

void SettingsPage::showSession() {
    UserSession* session = context().session;
    m_sectionUsers->setVisible(session != nullptr);
    for (QWidget* w : std::initializer_list<QWidget*>{m_userLabel, m_user, m_logOut, m_users, m_audit})
        w->setVisible(session != nullptr);
    if (!session) return;
    m_user->setText(session->describe());
    // The logged-in user is the name recorded with every change.
    m_operator->setReadOnly(true);
    m_operator->setText(session->identity() ? QString::fromStdString(session->identity()->name) : QString());
    m_logOut->setEnabled(session->identity().has_value());
    m_users->setEnabled(session->may(core::auth::Permission::ManageUsers));
    m_audit->setEnabled(session->may(core::auth::Permission::ViewAudit));
}

void SettingsPage::openUsers() {
    storage::UserStore* users = context().data().users();
    if (!users) return;
    UsersDialog dialog(*users, this);
    dialog.exec();
}

void SettingsPage::openAudit() {
    AuditDialog dialog(context(), this);
    dialog.exec();
}

void SettingsPage::retranslate() {
    m_sectionUsers->setText(tr("Users and audit"));
    m_userLabel->setText(tr("Logged in"));
    m_logOut->setText(tr("Log out"));
    m_users->setText(tr("Users…"));
    m_audit->setText(tr("Audit trail…"));
    showSession();
    m_sectionGeneral->setText(tr("Terminal"));
    m_languageLabel->setText(tr("Language"));
    m_operatorLabel->setText(tr("Operator"));
    m_operator->setPlaceholderText(tr("Name recorded with every change you apply"));
    m_databaseLabel->setText(tr("Run history"));
    m_machineLabel->setText(tr("This lathe in the plant database"));
    if (context().language) m_language->setCurrentIndex(m_language->findData(context().language->current()));
}

}  // namespace tt::ui
