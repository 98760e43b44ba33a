#pragma once

#include <QDialog>
#include <vector>

#include "core/storage/audit_store.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace tt::ui {

struct AppContext;

/// The audit trail: every change of a setting, calibration, tool, user or the controller with when,
/// who, role, old and new value; filtered by category and text; exported as CSV. A line above the buttons
/// shows the state of the trail's hash chain (intact, or which rows were edited, deleted or inserted).
class AuditDialog : public QDialog {
    Q_OBJECT
public:
    explicit AuditDialog(AppContext& context, QWidget* parent = nullptr);

    /// Reads the trail again with the filter of the fields; shows a refusal (role) or failure instead.
    void reload();
    /// Asks for a file (AppContext::prompt) and writes the shown records as CSV; true when written.
    bool exportCsv();

    QComboBox* categoryCombo() const { return m_category; }
    QLineEdit* textFilter() const { return m_text; }
    QTableWidget* table() const { return m_table; }
    /// The status line (how many records, a refusal, a write failure).
    QString statusText() const;
    /// The line on the hash chain ("Hash chain intact: 12 rows checked" or what was changed).
    QString chainText() const;
    /// Whether the last check found the chain intact.
    bool chainIntact() const { return m_chainIntact; }

    /// The chain's state in the user's language (one clause per problem, at most three named).
    static QString describeChain(const storage::AuditChainState& state);

    /// Translated name of an audit category ("Tool").
    static QString categoryName(const QString& category);

private:
    void showChain();

    AppContext& m_context;
    QComboBox* m_category;
    QLineEdit* m_text;
    QTableWidget* m_table;
    QLabel* m_status;
    QLabel* m_chain;
    bool m_chainIntact = false;
    std::vector<storage::AuditRecord> m_records;
};

}  // namespace tt::ui
