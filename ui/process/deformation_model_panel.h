#pragma once

#include <QWidget>

#include "config/deformation_model_config.h"
#include "core/model/deformation_model.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QTableWidget;

namespace tt::ui {

/// The statistics of the force-deformation model Y(a, f, z) as a planner judges it (paper 004): R²,
/// adjusted R², F against its table value, the residual 2σ, every term's coefficient, standard error and
/// t-value, the terms removed as insignificant; and the choice of terms for the next fit.
class DeformationModelPanel : public QWidget {
    Q_OBJECT
public:
    /// An empty panel ("no model yet"), cubic-z with stepwise removal chosen for the next fit.
    explicit DeformationModelPanel(QWidget* parent = nullptr);

    /// Shows `file` (or "no model" for nullptr).
    void showModel(const config::DeformationModelFile* file);
    /// The term set chosen for the next fit.
    core::DeformationTermSet termSet() const;
    /// Whether the next fit removes insignificant terms.
    bool stepwise() const;
    /// Sets every user-visible text (also on a language change).
    void retranslate();

    /// Widgets, for tests.
    QTableWidget* table() const { return m_table; }
    QLabel* summary() const { return m_summary; }
    QComboBox* termSetBox() const { return m_terms; }

private:
    void fillTable();

    const config::DeformationModelFile* m_file = nullptr;
    QLabel* m_termsLabel;
    QComboBox* m_terms;
    QCheckBox* m_stepwise;
    QLabel* m_summary;
    QTableWidget* m_table;
    QLabel* m_removed;
};

}  // namespace tt::ui
