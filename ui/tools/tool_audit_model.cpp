#include "ui/tools/tool_audit_model.h"

#include <QDateTime>

namespace tt::ui {

ToolAuditModel::ToolAuditModel(QObject* parent) : QAbstractTableModel(parent) {}

void ToolAuditModel::setEntries(std::vector<storage::ToolAuditEntry> entries) {
    beginResetModel();
    m_entries = std::move(entries);
    endResetModel();
}

int ToolAuditModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_entries.size());
}

int ToolAuditModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ToolAuditModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case When:
            return tr("When");
        case Who:
            return tr("Who");
        case Subject:
            return tr("Tool or material");
        case Field:
            return tr("Field");
        case Before:
            return tr("Old");
        case After:
            return tr("New");
        default:
            return {};
    }
}

QVariant ToolAuditModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || (role != Qt::DisplayRole && role != Qt::ToolTipRole)) return {};
    const storage::ToolAuditEntry& e = m_entries.at(static_cast<std::size_t>(index.row()));
    switch (index.column()) {
        case When: {
            const QDateTime utc = QDateTime::fromString(e.changedAt, Qt::ISODateWithMs);
            return utc.isValid() ? utc.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : e.changedAt;
        }
        case Who:
            return e.changedBy;
        case Subject:
            return e.subject;
        case Field:
            return e.field;
        case Before:
            return e.before.isEmpty() ? QStringLiteral("—") : e.before;
        case After:
            return e.after.isEmpty() ? QStringLiteral("—") : e.after;
        default:
            return {};
    }
}

}  // namespace tt::ui
