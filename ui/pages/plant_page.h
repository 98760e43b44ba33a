#pragma once

#include <QFutureWatcher>
#include <QString>

#include "ui/page.h"
#include "runtime/reports/plant_report.h"

class QLabel;
class QPushButton;
class QStackedWidget;
class QTableView;
class QTimer;

namespace tt::ui {

class EmptyState;
class PlantModel;

/// What a refresh of the Plant page read (in a worker thread).
struct PlantRefresh {
    runtime::PlantOverview overview;
    QString error;  ///< why the plant database could not be read; empty when it was
};

/// The quality engineer's and the shift leader's view of the shop: every machine that writes to the plant
/// database with its state (running, idle, offline with its last part's time), the parts its terminal still keeps,
/// the day's good / rework / scrap parts, per control point the Cpk of its last 125 parts with the change
/// against the 125 before, and its open alarms (ui/reports' plantOverview, the same as `trueturn plant`). A
/// click on a machine opens the Reports page with its reports. Refreshes itself every 10 s while shown, reading
/// in a worker thread with its own read-only connection.
class PlantPage : public Page {
    Q_OBJECT
public:
    explicit PlantPage(AppContext& context, QWidget* parent = nullptr);
    ~PlantPage() override;
    QString title() const override;
    void retranslate() override;

    /// Reads the plant database again in the worker (skipped while a read is still running).
    void refresh();
    /// Whether a read is running.
    bool busy() const { return m_watcher.isRunning(); }

    PlantModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    QLabel* status() const { return m_status; }
    /// How often the page reads again while shown, ms (by default).
    static constexpr int kRefreshMs = 10000;
    /// The interval of the automatic reads, ms (tests shorten it).
    void setRefreshMs(int ms);
    int refreshMs() const;

signals:
    /// A refresh ended (shown or failed).
    void refreshed();

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void finished();
    void showStatus();

    PlantModel* m_model;
    QLabel* m_source;
    QLabel* m_status;
    QPushButton* m_refresh;
    QStackedWidget* m_stack;
    EmptyState* m_empty;
    QTableView* m_table;
    QLabel* m_hint;
    QTimer* m_timer;
    QFutureWatcher<PlantRefresh> m_watcher;
    QString m_error;
    QDateTime m_readAt;
};

}  // namespace tt::ui
