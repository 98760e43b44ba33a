#include "ui/auth/users_dialog.h"

#include <QComboBox>
#include <QDateTime>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include "core/auth/idle_logout.h"
#include "core/storage/user_store.h"
#include "ui/auth/user_session.h"

namespace tt::ui {

using core::auth::Role;
using core::auth::SecretKind;

UsersDialog::UsersDialog(storage::UserStore& users, QWidget* parent)
    : QDialog(parent),
      m_users(users),
      m_table(new QTableWidget(this)),
      m_name(new QLineEdit(this)),
      m_role(new QComboBox(this)),
      m_kind(new QComboBox(this)),
      m_secret(new QLineEdit(this)),
      m_failures(new QSpinBox(this)),
      m_lockMinutes(new QSpinBox(this)),
      m_idle(new QSpinBox(this)),
      m_status(new QLabel(this)) {
    setWindowTitle(tr("Users"));
    setUpTable();
    setUpFields();
    buildLayout();
    resize(1200, 700);
    reload();
}

void UsersDialog::setUpTable() {
    m_table->setObjectName(QStringLiteral("usersTable"));
    m_table->setColumnCount(4);
    m_table->setHorizontalHeaderLabels({tr("Name"), tr("Role"), tr("Logs in with"), tr("State")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
}

void UsersDialog::setUpFields() {
    m_name->setObjectName(QStringLiteral("userName"));
    m_name->setMaxLength(storage::kMaxUserNameChars);
    for (Role r : core::auth::kAllRoles)
        m_role->addItem(UserSession::roleName(r), static_cast<int>(r));
    m_kind->addItem(tr("PIN (digits)"), static_cast<int>(SecretKind::Pin));
    m_kind->addItem(tr("Password"), static_cast<int>(SecretKind::Password));
    m_secret->setObjectName(QStringLiteral("userSecret"));
    m_secret->setEchoMode(QLineEdit::Password);
    m_secret->setMaxLength(core::auth::kMaxSecretChars);
    m_failures->setRange(1, core::auth::kMaxFailuresLimit);
    m_failures->setSuffix(tr(" failed log-ins"));
    m_lockMinutes->setRange(1, static_cast<int>(core::auth::kMaxLockSeconds / 60));
    m_lockMinutes->setSuffix(tr(" min"));
    m_idle->setObjectName(QStringLiteral("idleMinutes"));
    m_idle->setRange(core::auth::kMinIdleMinutes, core::auth::kMaxIdleMinutes);
    m_idle->setSuffix(tr(" min"));
    m_status->setObjectName(QStringLiteral("usersStatus"));
    m_status->setWordWrap(true);
}

void UsersDialog::buildLayout() {
    auto* top = new QHBoxLayout;
    top->addWidget(m_table, 1);
    top->addLayout(buildSide());
    auto* close = new QPushButton(tr("Close"), this);
    connect(close, &QPushButton::clicked, this, &QDialog::accept);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_status, 1);
    bottom->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 18, 24, 18);
    layout->addLayout(top, 1);
    layout->addLayout(bottom);
}

QVBoxLayout* UsersDialog::buildSide() {
    auto* form = new QFormLayout;
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Role"), m_role);
    form->addRow(tr("Logs in with"), m_kind);
    form->addRow(tr("PIN or password"), m_secret);
    QGridLayout* actions = buildUserActions();
    auto* policyTitle = new QLabel(tr("Log-in rules"), this);
    policyTitle->setObjectName(QStringLiteral("SectionTitle"));
    auto* policy = new QFormLayout;
    policy->addRow(tr("Lock out after"), m_failures);
    policy->addRow(tr("Lock-out lasts"), m_lockMinutes);
    policy->addRow(tr("Log out when idle for"), m_idle);
    auto* applyPolicyButton = new QPushButton(tr("Apply the rules"), this);
    connect(applyPolicyButton, &QPushButton::clicked, this, &UsersDialog::applyPolicy);

    auto* side = new QVBoxLayout;
    side->addLayout(form);
    side->addLayout(actions);
    side->addSpacing(12);
    side->addWidget(policyTitle);
    side->addLayout(policy);
    side->addWidget(applyPolicyButton);
    side->addStretch(1);
    return side;
}

QGridLayout* UsersDialog::buildUserActions() {
    auto* actions = new QGridLayout;
    const std::pair<QString, bool (UsersDialog::*)()> buttons[] = {{tr("Add user"), &UsersDialog::addUser},
                                                                   {tr("Set role"), &UsersDialog::setRole},
                                                                   {tr("Set PIN or password"), &UsersDialog::setSecret},
                                                                   {tr("Unlock"), &UsersDialog::unlock},
                                                                   {tr("Remove"), &UsersDialog::removeUser}};
    int i = 0;
    for (const auto& [text, slot] : buttons) {
        auto* b = new QPushButton(text, this);
        actions->addWidget(b, i / 2, i % 2);
        connect(b, &QPushButton::clicked, this, [this, slot = slot] { (this->*slot)(); });
        ++i;
    }
    return actions;
}

QString UsersDialog::statusText() const {
    return m_status->text();
}

void UsersDialog::reload() {
    const QString selected = selectedName();
    const std::vector<storage::UserRecord> users = m_users.users();
    m_table->setRowCount(static_cast<int>(users.size()));
    const qint64 now = QDateTime::currentSecsSinceEpoch();
    for (int row = 0; row < static_cast<int>(users.size()); ++row) {
        const storage::UserRecord& u = users[static_cast<std::size_t>(row)];
        const QString state =
            core::auth::isLocked(u.lockout, now)
                ? tr("locked until %1")
                      .arg(QDateTime::fromSecsSinceEpoch(u.lockout.lockedUntilS).toString(QStringLiteral("HH:mm")))
                : tr("active");
        const QString cells[] = {u.name, UserSession::roleName(u.role),
                                 u.secretKind == SecretKind::Pin ? tr("PIN") : tr("Password"), state};
        for (int col = 0; col < 4; ++col)
            m_table->setItem(row, col, new QTableWidgetItem(cells[col]));
        if (u.name == selected) m_table->selectRow(row);
    }
    m_table->resizeColumnsToContents();
    const storage::LoginPolicy p = m_users.policy();
    m_failures->setValue(p.lockout.maxFailures);
    m_lockMinutes->setValue(static_cast<int>(p.lockout.lockSeconds / 60));
    m_idle->setValue(p.idleMinutes);
}

QString UsersDialog::selectedName() const {
    const QList<QTableWidgetItem*> items = m_table->selectedItems();
    return items.isEmpty() ? QString() : m_table->item(items.front()->row(), 0)->text();
}

bool UsersDialog::run(const QString& done, const std::function<void()>& work) {
    try {
        work();
    } catch (const std::exception& e) {
        m_status->setText(tr("Not changed: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    m_secret->clear();
    reload();
    m_status->setText(done);
    return true;
}

bool UsersDialog::addUser() {
    const QString name = m_name->text().trimmed();
    return run(tr("%1 added.").arg(name), [&] {
        m_users.addUser(name, static_cast<Role>(m_role->currentData().toInt()), m_secret->text().toStdString(),
                        static_cast<SecretKind>(m_kind->currentData().toInt()));
    });
}

bool UsersDialog::setRole() {
    const QString name = selectedName();
    return run(tr("%1 is now %2.").arg(name, m_role->currentText()), [&] {
        if (name.isEmpty()) throw std::invalid_argument(tr("select a user first").toStdString());
        m_users.setRole(name, static_cast<Role>(m_role->currentData().toInt()));
    });
}

bool UsersDialog::setSecret() {
    const QString name = selectedName();
    return run(tr("New PIN or password of %1 stored.").arg(name), [&] {
        if (name.isEmpty()) throw std::invalid_argument(tr("select a user first").toStdString());
        m_users.setSecret(name, m_secret->text().toStdString(), static_cast<SecretKind>(m_kind->currentData().toInt()));
    });
}

bool UsersDialog::unlock() {
    const QString name = selectedName();
    return run(tr("%1 unlocked.").arg(name), [&] {
        if (name.isEmpty()) throw std::invalid_argument(tr("select a user first").toStdString());
        m_users.unlock(name);
    });
}

bool UsersDialog::removeUser() {
    const QString name = selectedName();
    return run(tr("%1 removed.").arg(name), [&] {
        if (name.isEmpty()) throw std::invalid_argument(tr("select a user first").toStdString());
        m_users.removeUser(name);
    });
}

bool UsersDialog::applyPolicy() {
    return run(tr("Log-in rules stored."), [&] {
        storage::LoginPolicy p;
        p.lockout.maxFailures = m_failures->value();
        p.lockout.lockSeconds = static_cast<std::int64_t>(m_lockMinutes->value()) * 60;
        p.idleMinutes = m_idle->value();
        m_users.setPolicy(p);
    });
}

}  // namespace tt::ui
