#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/storage/tool_store.h"

namespace tt::ui {

/// The audit record of the tool table, newest first: when (local time), who, what, field, old, new.
class ToolAuditModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { When, Who, Subject, Field, Before, After, ColumnCount };

    explicit ToolAuditModel(QObject* parent = nullptr);
    void setEntries(std::vector<storage::ToolAuditEntry> entries);
    const std::vector<storage::ToolAuditEntry>& entries() const { return m_entries; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    std::vector<storage::ToolAuditEntry> m_entries;
};

}  // namespace tt::ui
