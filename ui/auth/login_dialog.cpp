#include "ui/auth/login_dialog.h"

#include <QComboBox>
#include <QDateTime>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/auth/secret_hash.h"
#include "core/storage/user_store.h"
#include "ui/auth/user_session.h"

namespace tt::ui {

LoginDialog::LoginDialog(storage::UserStore& users, UserSession& session, Leave leave, QWidget* parent)
    : QDialog(parent),
      m_users(users),
      m_session(session),
      m_leave(leave),
      m_clockS([] { return static_cast<std::int64_t>(QDateTime::currentSecsSinceEpoch()); }),
      m_user(new QComboBox(this)),
      m_secret(new QLineEdit(this)),
      m_message(new QLabel(this)) {
    setWindowTitle(tr("Log in"));
    buildLayout();
    connect(m_secret, &QLineEdit::returnPressed, this, &LoginDialog::attempt);
    m_secret->setFocus();
}

void LoginDialog::buildLayout() {
    auto* title = new QLabel(tr("Log in to TrueTurn"), this);
    title->setObjectName(QStringLiteral("SectionTitle"));
    m_user->setObjectName(QStringLiteral("loginUser"));
    for (const storage::UserRecord& u : m_users.users())
        m_user->addItem(u.name);
    m_secret->setObjectName(QStringLiteral("loginSecret"));
    m_secret->setEchoMode(QLineEdit::Password);
    m_secret->setMaxLength(core::auth::kMaxSecretChars);
    m_secret->setPlaceholderText(tr("Password or PIN"));
    m_secret->setStyleSheet(QStringLiteral("font-size: 18pt;"));
    m_message->setObjectName(QStringLiteral("authProblem"));
    m_message->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
    m_message->setWordWrap(true);
    m_message->setMinimumHeight(96);  // three lines of the lock-out message without squeezing the form

    auto* form = new QFormLayout;
    form->setVerticalSpacing(14);
    form->addRow(tr("User"), m_user);
    form->addRow(tr("Password or PIN"), m_secret);

    auto* left = new QVBoxLayout;
    left->setSpacing(16);
    left->addWidget(title);
    left->addLayout(form);
    left->addWidget(m_message);
    left->addStretch(1);
    left->addLayout(buildButtons());
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(32, 24, 32, 24);
    layout->setSpacing(32);
    layout->addLayout(left, 1);
    layout->addWidget(buildKeypad());
    setMinimumWidth(900);
}

QHBoxLayout* LoginDialog::buildButtons() {
    auto* logIn = new QPushButton(tr("Log in"), this);
    logIn->setObjectName(QStringLiteral("loginButton"));
    logIn->setProperty("role", QStringLiteral("primary"));
    logIn->setDefault(true);
    logIn->setMinimumHeight(64);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    if (m_leave != Leave::Never) {
        auto* leave = new QPushButton(m_leave == Leave::Quit ? tr("Quit") : tr("Cancel"), this);
        leave->setObjectName(QStringLiteral("leaveButton"));
        leave->setMinimumHeight(64);
        buttons->addWidget(leave);
        connect(leave, &QPushButton::clicked, this, &QDialog::reject);
    }
    buttons->addWidget(logIn);
    connect(logIn, &QPushButton::clicked, this, &LoginDialog::attempt);
    return buttons;
}

QWidget* LoginDialog::buildKeypad() {
    auto* pad = new QWidget(this);
    pad->setObjectName(QStringLiteral("loginKeypad"));
    auto* grid = new QGridLayout(pad);
    grid->setSpacing(10);
    const QString keys[] = {QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"), QStringLiteral("4"),
                            QStringLiteral("5"), QStringLiteral("6"), QStringLiteral("7"), QStringLiteral("8"),
                            QStringLiteral("9"), tr("Clear"),         QStringLiteral("0"), QStringLiteral("⌫")};
    for (int i = 0; i < 12; ++i) {
        auto* key = new QPushButton(keys[i], pad);
        key->setObjectName(QStringLiteral("key_%1").arg(i));
        key->setFixedSize(96, 76);
        key->setFocusPolicy(Qt::NoFocus);
        // The word key (Clear) in a smaller size so it fits in every language.
        key->setStyleSheet(i == 9 ? QStringLiteral("font-size: 13pt; font-weight: bold; padding: 0px;")
                                  : QStringLiteral("font-size: 20pt; font-weight: bold; padding: 0px;"));
        grid->addWidget(key, i / 3, i % 3);
        connect(key, &QPushButton::clicked, this, [this, i, text = keys[i]] {
            if (i == 9)
                m_secret->clear();
            else if (i == 11)
                m_secret->backspace();
            else
                m_secret->insert(text);
        });
    }
    return pad;
}

QString LoginDialog::messageText() const {
    return m_message->text();
}

bool LoginDialog::attempt() {
    const QString name = m_user->currentText();
    const std::string secret = m_secret->text().toStdString();
    m_secret->clear();
    try {
        const storage::LoginOutcome outcome = m_users.logIn(name, secret, m_clockS());
        switch (outcome.result) {
            case storage::LoginOutcome::Result::LoggedIn:
                m_session.logIn(*outcome.identity, m_users.policy().idleMinutes);
                m_message->clear();
                accept();
                return true;
            case storage::LoginOutcome::Result::Refused:
                m_message->setText(
                    tr("Wrong name or password. %n attempt(s) left before the lock-out.", "", outcome.attemptsLeft));
                return false;
            case storage::LoginOutcome::Result::Locked:
                m_message->setText(tr("Too many failed log-ins: %1 is locked until %2. An administrator can "
                                      "unlock it.")
                                       .arg(name, QDateTime::fromSecsSinceEpoch(outcome.lockedUntilS)
                                                      .toLocalTime()
                                                      .toString(QStringLiteral("HH:mm:ss"))));
                return false;
        }
    } catch (const std::exception& e) {
        m_message->setText(tr("Cannot log in: %1").arg(QString::fromStdString(e.what())));
    }
    return false;
}

void LoginDialog::reject() {
    if (m_leave != Leave::Never) QDialog::reject();  // otherwise Escape does not leave the terminal unlocked
}

}  // namespace tt::ui
