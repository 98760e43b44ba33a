#pragma once

#include <QWidget>
#include <optional>
#include <vector>

#include "core/ports/history_store.h"
#include "core/quality/point_analysis.h"
#include "core/storage/measurement_query.h"

class QComboBox;
class QDateEdit;
class QLabel;
class QSpinBox;

namespace tt::ui {

/// The choice of the Reports page: machine, run (or all), date range of the stored parts, subgroup size,
/// chart kind and phase-I baseline. Gives the history filter and the statistics' settings.
class ReportFilterBar : public QWidget {
    Q_OBJECT
public:
    explicit ReportFilterBar(QWidget* parent = nullptr);

    /// Fills the machine and run lists from the stored runs, keeping the current choice where it remains.
    void setRuns(const std::vector<core::RunSummary>& runs);
    /// Chooses `machine` with all its runs and any date (the Plant page opens a machine's reports).
    void selectMachine(const QString& machine);
    /// The readings chosen (every point: the page shows one and all side by side).
    storage::MeasurementFilter filter() const;
    /// The chart settings; throws std::invalid_argument on a bad combination (I-MR with subgroups).
    core::PointAnalysisSettings settings() const;
    void retranslate();

    QComboBox* machines() const { return m_machine; }
    QComboBox* runs() const { return m_run; }
    QDateEdit* from() const { return m_from; }
    QDateEdit* to() const { return m_to; }
    QSpinBox* subgroup() const { return m_subgroup; }
    QComboBox* chart() const { return m_chart; }
    QSpinBox* baseline() const { return m_baseline; }

signals:
    /// The choice changed (the page analyses again on request).
    void changed();

private:
    void fillRuns();

    std::vector<core::RunSummary> m_runs;
    QLabel* m_machineLabel;
    QComboBox* m_machine;
    QLabel* m_runLabel;
    QComboBox* m_run;
    QLabel* m_fromLabel;
    QDateEdit* m_from;
    QLabel* m_toLabel;
    QDateEdit* m_to;
    QLabel* m_subgroupLabel;
    QSpinBox* m_subgroup;
    QLabel* m_chartLabel;
    QComboBox* m_chart;
    QLabel* m_baselineLabel;
    QSpinBox* m_baseline;
};

}  // namespace tt::ui
