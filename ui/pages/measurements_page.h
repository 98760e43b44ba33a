#pragma once

#include <memory>
#include <string>

#include "ui/page.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QStackedWidget;
class QTableView;

namespace tt::storage {
class Database;
class SqlHistoryStore;
}  // namespace tt::storage

namespace tt::ui {

class EmptyState;
class MeasurementsModel;

/// The recorded parts of a run and their measurements, read from the run history: a row per part and
/// control point with the measured and nominal diameter, accepted or rejected with the reason, and the
/// correction the part received. Refreshed whenever the page is shown.
class MeasurementsPage : public Page {
    Q_OBJECT
public:
    explicit MeasurementsPage(AppContext& context, QWidget* parent = nullptr);
    ~MeasurementsPage() override;
    QString title() const override;
    void retranslate() override;

    /// Reads the runs and the chosen run's parts again.
    void refresh();
    MeasurementsModel* model() const { return m_model; }
    QComboBox* runs() const { return m_runs; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    /// The controller of a stored run ("lqg") as the Run page names it.
    static QString controllerName(const std::string& controller);
    /// The stored state of a run ("complete") in the operator's words.
    static QString runStatusName(const std::string& status);
    void loadRun();
    bool openHistory();

    storage::SqlHistoryStore* m_history = nullptr;  ///< from the application's data access object
    QString m_problem;
    QLabel* m_runLabel;
    QComboBox* m_runs;
    QCheckBox* m_onlyProblems;
    QPushButton* m_refresh;
    QLabel* m_summary;
    QStackedWidget* m_stack;
    EmptyState* m_empty;
    QTableView* m_table;
    MeasurementsModel* m_model;
};

}  // namespace tt::ui
