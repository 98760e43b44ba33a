#pragma once

#include <QAbstractTableModel>
#include <QStringList>
#include <vector>

#include "core/model/tool_table_csv.h"

namespace tt::ui {

class ToolTableModel;

/// The preview of a tool-table CSV import (issue 6: "CSV import with a preview and conflict
/// handling"): each row of the file against the table as it is now: new, unchanged, in conflict
/// (same id, other values: keep the table's or take the file's) or invalid (skipped, with the
/// reasons). Nothing changes in the table until the page imports what the preview says.
class ToolImportModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Line, Id, Status, Details, Action, ColumnCount };
    enum class State { New, Unchanged, Conflict, Invalid };
    enum class Choice { TakeFile, KeepTable };

    struct Row {
        core::ToolCsvRow csv;
        State state = State::New;
        QStringList details;  ///< differences ("overhang_mm: 400 → 450") or problems
        Choice choice = Choice::KeepTable;
    };

    explicit ToolImportModel(QObject* parent = nullptr);

    /// Compares the file's rows with the table's current (edited) tools.
    void setRows(const std::vector<core::ToolCsvRow>& rows, const ToolTableModel& table);
    /// Sets the choice of every conflict.
    void setAllConflicts(Choice choice);
    /// The tools to import: new ones and conflicts taken from the file.
    std::vector<core::ToolRecord> toImport() const;
    int count(State state) const;
    const Row& row(int index) const { return m_rows.at(static_cast<std::size_t>(index)); }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// The Action of a conflict row: "file" or "table" (EditRole), or a Choice as int.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    /// Translated name of a choice, as the Action column shows it.
    static QString choiceText(Choice choice);

private:
    std::vector<Row> m_rows;
};

}  // namespace tt::ui
