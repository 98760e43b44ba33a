#include "ui/auth/audit_dialog.h"

#include <QComboBox>
#include <QDateTime>
#include <QFile>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStringList>
#include <QTableWidget>
#include <QVBoxLayout>

#include "ui/app_context.h"
#include "ui/auth/user_session.h"
#include "ui/prompt.h"

namespace tt::ui {

namespace {

QString localTime(const QString& isoUtc) {
    const QDateTime t = QDateTime::fromString(isoUtc, Qt::ISODateWithMs);
    return t.isValid() ? t.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : isoUtc;
}

/// A stored value in the user's language where it is one of the product's own words (a role key, a
/// log-in event, a secret's kind); anything else (numbers, names, tool fields) as stored.
QString displayValue(const QString& value) {
    for (core::auth::Role role : core::auth::kAllRoles)
        if (value == QString::fromStdString(core::auth::roleKey(role))) return UserSession::roleName(role);
    if (value == QLatin1String("logged in")) return AuditDialog::tr("logged in");
    if (value == QLatin1String("password set")) return AuditDialog::tr("password set");
    if (value == QLatin1String("pin set")) return AuditDialog::tr("PIN set");
    if (value == QLatin1String("unlocked")) return AuditDialog::tr("unlocked");
    return value;
}

QString displaySubject(const QString& subject) {
    if (subject.startsWith(QLatin1String("user "))) return AuditDialog::tr("user %1").arg(subject.mid(5));
    return subject;
}

}  // namespace

QString AuditDialog::categoryName(const QString& category) {
    namespace c = storage::audit_category;
    if (category == c::kSetting) return tr("Setting");
    if (category == c::kCalibration) return tr("Calibration");
    if (category == c::kTool) return tr("Tool");
    if (category == c::kUser) return tr("User");
    if (category == c::kController) return tr("Controller");
    if (category == c::kSession) return tr("Log-in");
    return category;
}

AuditDialog::AuditDialog(AppContext& context, QWidget* parent)
    : QDialog(parent),
      m_context(context),
      m_category(new QComboBox(this)),
      m_text(new QLineEdit(this)),
      m_table(new QTableWidget(this)),
      m_status(new QLabel(this)),
      m_chain(new QLabel(this)) {
    setWindowTitle(tr("Audit trail"));
    m_category->setObjectName(QStringLiteral("auditCategory"));
    m_category->addItem(tr("All changes"), QString());
    namespace c = storage::audit_category;
    for (const QString& key : {c::kSetting, c::kCalibration, c::kTool, c::kUser, c::kController, c::kSession})
        m_category->addItem(categoryName(key), key);
    m_text->setObjectName(QStringLiteral("auditText"));
    m_text->setPlaceholderText(tr("Filter: name, tool, field or value"));
    m_text->setClearButtonEnabled(true);
    m_table->setObjectName(QStringLiteral("auditTable"));
    m_table->setColumnCount(8);
    m_table->setHorizontalHeaderLabels(
        {tr("When"), tr("Who"), tr("Role"), tr("What"), tr("Subject"), tr("Field"), tr("Old value"), tr("New value")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_status->setObjectName(QStringLiteral("auditStatus"));
    m_status->setWordWrap(true);
    m_chain->setObjectName(QStringLiteral("auditChain"));
    m_chain->setWordWrap(true);

    auto* exportButton = new QPushButton(tr("Export CSV…"), this);
    exportButton->setObjectName(QStringLiteral("auditExport"));
    auto* close = new QPushButton(tr("Close"), this);
    auto* filters = new QHBoxLayout;
    filters->addWidget(new QLabel(tr("Show"), this));
    filters->addWidget(m_category);
    filters->addWidget(m_text, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_status, 1);
    buttons->addWidget(exportButton);
    buttons->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 18, 24, 18);
    layout->addLayout(filters);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_chain);
    layout->addLayout(buttons);
    resize(1240, 720);

    connect(m_category, &QComboBox::currentIndexChanged, this, &AuditDialog::reload);
    connect(m_text, &QLineEdit::textChanged, this, &AuditDialog::reload);
    connect(exportButton, &QPushButton::clicked, this, &AuditDialog::exportCsv);
    connect(close, &QPushButton::clicked, this, &QDialog::accept);
    reload();
    showChain();  // once: the chain is the whole table's, not the filter's
}

QString AuditDialog::statusText() const {
    return m_status->text();
}

QString AuditDialog::chainText() const {
    return m_chain->text();
}

QString AuditDialog::describeChain(const storage::AuditChainState& state) {
    using Kind = storage::AuditChainProblem::Kind;
    if (state.intact()) return tr("Hash chain intact: %n row(s) checked.", "", static_cast<int>(state.rows));
    QStringList clauses;
    for (const storage::AuditChainProblem& p : state.problems) {
        if (clauses.size() == 3) {
            clauses << QStringLiteral("…");
            break;
        }
        if (p.kind == Kind::Edited) clauses << tr("row %1 edited").arg(p.rowId);
        if (p.kind == Kind::Inserted) clauses << tr("row %1 inserted").arg(p.rowId);
        if (p.kind == Kind::Head) clauses << tr("the chain's head does not match its last row");
        if (p.kind == Kind::Deleted && p.rowId)
            clauses << tr("%n row(s) deleted before row %1", "", static_cast<int>(p.missingRows)).arg(p.rowId);
        if (p.kind == Kind::Deleted && !p.rowId)
            clauses << tr("%n row(s) deleted at the end", "", static_cast<int>(p.missingRows));
    }
    return tr("Hash chain BROKEN: the trail was changed outside TrueTurn (%1).")
        .arg(clauses.join(QStringLiteral("; ")));
}

void AuditDialog::showChain() {
    storage::AuditStore* audit = m_context.data().audit();
    m_chainIntact = false;
    if (!audit) {
        m_chain->clear();
        return;
    }
    try {
        const storage::AuditChainState state = audit->verifyChain();
        m_chainIntact = state.intact();
        m_chain->setText(describeChain(state));
    } catch (const std::exception& e) {
        m_chain->setText(tr("Hash chain not checked: %1").arg(QString::fromStdString(e.what())));
    }
    m_chain->setStyleSheet(m_chainIntact ? QString() : QStringLiteral("color: #b00020; font-weight: bold;"));
}

void AuditDialog::reload() {
    m_records.clear();
    m_table->setRowCount(0);
    storage::AuditStore* audit = m_context.data().audit();
    if (!audit) {
        m_status->setText(tr("The database cannot be opened: %1").arg(m_context.data().problem()));
        return;
    }
    storage::AuditFilter filter;
    filter.category = m_category->currentData().toString();
    filter.text = m_text->text().trimmed();
    try {
        m_records = audit->query(filter);
    } catch (const std::exception& e) {
        m_status->setText(tr("Not shown: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    m_table->setRowCount(static_cast<int>(m_records.size()));
    for (int row = 0; row < static_cast<int>(m_records.size()); ++row) {
        const storage::AuditRecord& r = m_records[static_cast<std::size_t>(row)];
        const QString role =
            r.role.isEmpty() ? QString() : UserSession::roleName(core::auth::roleFromKey(r.role.toStdString()));
        const QString cells[] = {localTime(r.changedAt),
                                 r.changedBy,
                                 role,
                                 categoryName(r.change.category),
                                 displaySubject(r.change.subject),
                                 r.change.field,
                                 displayValue(r.change.before),
                                 displayValue(r.change.after)};
        for (int col = 0; col < 8; ++col)
            m_table->setItem(row, col, new QTableWidgetItem(cells[col]));
    }
    m_table->resizeColumnsToContents();
    m_status->setText(tr("%n record(s)", "", static_cast<int>(m_records.size())));
}

bool AuditDialog::exportCsv() {
    if (!m_context.prompt) return false;
    const QString path = m_context.prompt->saveFileName(this, tr("Export the audit trail"),
                                                        QStringLiteral("trueturn-audit.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty()) return false;
    QFile file(path);
    const QByteArray bytes = storage::auditCsv(m_records).toUtf8();
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size() || !file.flush()) {
        m_status->setText(tr("Not written: %1 (%2)").arg(path, file.errorString()));
        return false;
    }
    file.close();
    m_status->setText(tr("%n record(s) written to %1", "", static_cast<int>(m_records.size())).arg(path));
    return true;
}

}  // namespace tt::ui
