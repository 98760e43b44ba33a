#include "ui/auth/first_start_dialog.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/auth/secret_hash.h"
#include "core/storage/user_store.h"
#include "ui/auth/user_session.h"

namespace tt::ui {

FirstStartDialog::FirstStartDialog(storage::UserStore& users, UserSession& session, QWidget* parent)
    : QDialog(parent),
      m_users(users),
      m_session(session),
      m_name(new QLineEdit(this)),
      m_password(new QLineEdit(this)),
      m_repeat(new QLineEdit(this)),
      m_problem(new QLabel(this)) {
    setWindowTitle(tr("First start: create the administrator"));
    auto* title = new QLabel(tr("Create the administrator"), this);
    title->setObjectName(QStringLiteral("SectionTitle"));
    auto* intro = new QLabel(tr("No user exists yet. The administrator adds the operators, engineers and quality "
                                "staff and sets what they may change. The password needs at least %1 characters.")
                                 .arg(core::auth::kMinPasswordChars),
                             this);
    intro->setWordWrap(true);
    m_name->setObjectName(QStringLiteral("adminName"));
    m_name->setMaxLength(storage::kMaxUserNameChars);
    m_password->setObjectName(QStringLiteral("adminPassword"));
    m_repeat->setObjectName(QStringLiteral("adminRepeat"));
    for (QLineEdit* e : {m_password, m_repeat}) {
        e->setEchoMode(QLineEdit::Password);
        e->setMaxLength(core::auth::kMaxSecretChars);
    }
    m_problem->setObjectName(QStringLiteral("authProblem"));
    m_problem->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
    m_problem->setWordWrap(true);

    auto* form = new QFormLayout;
    form->setVerticalSpacing(14);
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Password"), m_password);
    form->addRow(tr("Repeat the password"), m_repeat);

    auto* create = new QPushButton(tr("Create and log in"), this);
    create->setObjectName(QStringLiteral("createAdmin"));
    create->setProperty("role", QStringLiteral("primary"));
    create->setDefault(true);
    auto* quit = new QPushButton(tr("Quit"), this);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(quit);
    buttons->addWidget(create);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(32, 24, 32, 24);
    layout->setSpacing(16);
    layout->addWidget(title);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addStretch(1);
    layout->addLayout(buttons);
    setMinimumWidth(640);

    connect(create, &QPushButton::clicked, this, &FirstStartDialog::create);
    connect(quit, &QPushButton::clicked, this, &QDialog::reject);
}

QString FirstStartDialog::problemText() const {
    return m_problem->text();
}

void FirstStartDialog::showProblem(const QString& text) {
    m_problem->setText(text);
}

bool FirstStartDialog::create() {
    if (m_password->text() != m_repeat->text()) {
        showProblem(tr("The two passwords differ; type them again."));
        m_repeat->clear();
        return false;
    }
    try {
        const std::string secret = m_password->text().toStdString();
        const core::auth::Identity admin =
            m_users.createFirstAdministrator(m_name->text(), secret, core::auth::SecretKind::Password);
        m_session.logIn(admin, m_users.policy().idleMinutes);
    } catch (const std::exception& e) {
        showProblem(tr("Not created: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    showProblem(QString());
    accept();
    return true;
}

}  // namespace tt::ui
