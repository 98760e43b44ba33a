#pragma once

#include <QAbstractTableModel>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/model/tool_table.h"
#include "core/storage/tool_store.h"

class QUndoStack;

namespace tt::ui {

/// One row of the tool-table editor: the stored tool (none for a new row) and the edited one.
struct ToolRow {
    std::optional<core::ToolRecord> stored;
    core::ToolRecord edited;
    bool removed = false;  ///< removal pending until applied

    /// New, removed, or different from the stored tool.
    bool pending() const;
};

/// The tool stiffness table as an editable model (issue 6, item 1): each cell is parsed when
/// entered (units named in the refusal), every edit is an undoable command on undoStack(),
/// edits stay pending (highlighted) until the page applies them, rows with problems are marked
/// and listed. Rows are only appended or flagged as removed until applied, so row numbers stay
/// valid for the undo history.
class ToolTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    /// Columns: the editable tool fields, then computed ones.
    enum Column {
        Id,
        Name,
        Section,
        Diameter,
        Width,
        Height,
        Overhang,
        Material,
        YoungsModulus,
        MeasuredStiffness,
        MeasuredOn,
        MeasuredBy,
        CurrentToForceGain,
        ComputedStiffness,  ///< 3EI/l³, read only
        Slenderness,        ///< L/d, read only
        ColumnCount
    };
    /// Roles beyond Qt's: whether a cell differs from the stored tool, whether its row has problems.
    enum Role { PendingRole = Qt::UserRole + 1, ProblemRole };

    explicit ToolTableModel(QObject* parent = nullptr);

    /// Replaces everything with the stored table and the materials list; clears the undo history.
    void load(const std::vector<core::ToolRecord>& stored, const std::vector<core::Material>& materials);
    /// Updates the materials list (for the Material column) without touching the rows.
    void setMaterials(const std::vector<core::Material>& materials);
    const std::vector<core::Material>& materials() const { return m_materials; }
    /// Who is editing: filled in as "measured by" when a measured stiffness is first entered.
    void setOperatorName(const QString& name) { m_operator = name; }
    QUndoStack* undoStack() const { return m_undo; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// Edits a cell from text (EditRole); refuses text that is not a value of the field with
    /// editRefused(row, column, reason) and returns false. Choosing a listed material also sets E.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    /// Adds a new tool with a free id (T1, T2, ...); returns its row. Undoable.
    int addTool();
    /// Marks rows as removed (pending). Undoable as one step.
    void removeTools(const QList<int>& rows);
    /// Adds new tools and replaces existing ones by id, as one undoable step named `label`.
    void importTools(const std::vector<core::ToolRecord>& tools, const QString& label);
    /// Sets a whole row (one undoable step); used by the edit commands and imports.
    void replaceTool(int row, const core::ToolRecord& tool, const QString& label);

    const ToolRow& toolRow(int row) const { return m_rows.at(static_cast<std::size_t>(row)); }
    /// Row of the (not removed) tool with this id, or -1.
    int rowOfId(const std::string& id) const;
    /// The tools as shown (removed rows left out).
    std::vector<core::ToolRecord> currentTools() const;
    /// Rows that differ from what is stored.
    int pendingCount() const;
    bool hasPending() const { return pendingCount() > 0; }
    /// "T3: overhang l: 0 mm must be between 10 and 5000 mm", one per problem of a row that is not removed.
    QStringList problems() const;
    /// Problems of one row (validation plus a duplicate id).
    QStringList rowProblems(int row) const;
    /// What the store needs to apply the pending rows.
    std::vector<storage::ToolEdit> pendingEdits() const;
    /// After a successful apply: `stored` becomes the loaded state, the undo history is cleared.
    void markApplied(const std::vector<core::ToolRecord>& stored);
    /// Drops every pending edit (back to the stored table) and clears the undo history.
    void discard();

    /// The translated column title with its unit ("Overhang l, mm").
    static QString columnTitle(int column);

signals:
    void editRefused(int row, int column, const QString& reason);
    void pendingChanged();

private:
    friend class ToolRowCommand;
    friend class AddToolCommand;
    void setRow(int row, const ToolRow& value);
    void appendRow(const ToolRow& value);
    void dropLastRow();
    QString nextFreeId() const;
    double modulusOf(const std::string& material) const;
    /// What a cell shows: the field's text, the section's shape in words, the computed stiffness and
    /// slenderness ("—" when the tool's data do not allow them).
    QString displayText(const ToolRow& r, int column) const;
    /// A cell's colour: removed, computed or not editable, a problem in the row, an edit not applied.
    QVariant background(const QModelIndex& index, bool cellPending) const;
    /// The row's problems, removal and the value applied before an edit.
    QVariant toolTip(const QModelIndex& index, bool cellPending) const;

    std::vector<ToolRow> m_rows;
    std::vector<core::Material> m_materials;
    QString m_operator;
    QUndoStack* m_undo;
};

}  // namespace tt::ui
