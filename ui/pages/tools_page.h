#pragma once

#include <QString>
#include <memory>

#include "core/model/tool_stiffness.h"
#include "ui/page.h"

class QLabel;
class QPushButton;
class QStackedWidget;
class QTabWidget;
class QTableView;

namespace tt::storage {
class Database;
class ToolStore;
}  // namespace tt::storage

namespace tt::ui {

class EmptyState;
class MaterialsModel;
class ToolAuditModel;
class ToolImportModel;
class ToolTableModel;

/// The Tools page (issue 6, item 1): the tool stiffness table as a real editor. Cells are
/// checked as they are entered (units in the column titles and the refusals), edits are undoable
/// and stay highlighted until applied, CSV files are imported through a preview that shows new,
/// unchanged, conflicting and unreadable rows, the table exports as CSV, the materials list with
/// Young's modulus is edited on its own tab, and every applied change is in the audit record with
/// the operator's name (Settings) and the time. Stored through storage::ToolStore.
class ToolsPage : public Page {
    Q_OBJECT
public:
    explicit ToolsPage(AppContext& context, QWidget* parent = nullptr);
    ~ToolsPage() override;
    QString title() const override;
    void retranslate() override;
    QString unappliedEdits() const override;

    /// Stores the pending edits (refused with a warning while a row has problems or no operator
    /// name is set); returns whether they were stored.
    bool applyChanges();
    /// Drops the pending edits after asking.
    void discardChanges();
    /// Asks for a CSV file and shows the import preview.
    void importCsv();
    /// Reads `path` and shows the preview; false (with a warning) when the file cannot be used.
    bool previewImport(const QString& path);
    /// Imports what the preview says into the table (pending, one undo step).
    void confirmImport();
    void cancelImport();
    /// Asks for a file name and writes the table as shown.
    void exportCsv();
    void addTool();
    void removeSelectedTools();
    void addMaterial();
    void removeSelectedMaterial();

    ToolTableModel* toolModel() const { return m_model; }
    ToolImportModel* importModel() const { return m_importModel; }
    MaterialsModel* materialsModel() const { return m_materialsModel; }
    ToolAuditModel* auditModel() const { return m_auditModel; }
    QTableView* toolView() const { return m_table; }
    QTabWidget* tabs() const { return m_tabs; }
    bool previewShown() const;
    /// The last status line ("2 tools pending ...").
    QString statusText() const;

private:
    void buildEditor();
    void buildImportPreview();
    void openStore();
    void reloadFromStore();
    void updateState();
    void onMaterialEdited(const QString& previousName, const core::Material& material);
    QString operatorName() const;
    bool requireOperator(const QString& action);
    void showStatus(const QString& text, bool problem = false);

    storage::ToolStore* m_store = nullptr;  ///< from the application's data access object
    QString m_storeError;
    QString m_lastStatus;
    bool m_lastStatusIsProblem = false;
    bool m_lastStatusIsHint = false;  ///< the idle hint, shown again in a new language
    QString m_importFile;

    ToolTableModel* m_model;
    ToolImportModel* m_importModel;
    MaterialsModel* m_materialsModel;
    ToolAuditModel* m_auditModel;

    QStackedWidget* m_stack;
    QWidget* m_editor;
    QWidget* m_preview;
    EmptyState* m_storageProblem;
    QTabWidget* m_tabs;
    QTableView* m_table;
    QTableView* m_materialsView;
    QTableView* m_auditView;
    QTableView* m_importView;
    QLabel* m_status;
    QLabel* m_importTitle;
    QLabel* m_importSummary;
    QLabel* m_materialsHint;
    QPushButton* m_add;
    QPushButton* m_remove;
    QPushButton* m_undo;
    QPushButton* m_redo;
    QPushButton* m_import;
    QPushButton* m_export;
    QPushButton* m_discard;
    QPushButton* m_apply;
    QPushButton* m_addMaterial;
    QPushButton* m_removeMaterial;
    QPushButton* m_takeAll;
    QPushButton* m_keepAll;
    QPushButton* m_importConfirm;
    QPushButton* m_importCancel;
};

}  // namespace tt::ui
