#pragma once

#include <QWidget>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/storage/measurement_query.h"
#include "runtime/reports/point_report.h"

class QComboBox;
class QGridLayout;
class QLabel;
class QSpinBox;
class QTableWidget;
class QTabWidget;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

/// The results of the Reports page in tabs: the control chart pair of the chosen point with its rule
/// violations; its histogram with the capability table; the profile of a chosen part along the shaft with
/// its tolerance band; every point's control chart side by side.
class ReportViews : public QWidget {
    Q_OBJECT
public:
    explicit ReportViews(QWidget* parent = nullptr);

    /// Shows a new report (the readings for the part profiles); `adaptationsError`: why the controller changes of the
    /// runs could not be read (empty: they were).
    void show(std::vector<storage::MeasurementRow> rows, std::vector<runtime::PointReport> points,
              QString adaptationsError = {});
    /// The point shown in the chart and distribution tabs (index into points()).
    void showPoint(int index);
    /// The part (1-based, in production order over the chosen runs) whose profile is shown.
    void showPart(int number);
    void retranslate();

    const std::vector<runtime::PointReport>& points() const { return m_points; }
    const std::vector<storage::MeasurementRow>& rows() const { return m_rows; }
    QTabWidget* tabs() const { return m_tabs; }
    QComboBox* pointChoice() const { return m_point; }
    QSpinBox* partChoice() const { return m_part; }
    plot::Chart* location() const { return m_location; }
    plot::Chart* spread() const { return m_spread; }
    plot::Chart* histogram() const { return m_histogram; }
    plot::Chart* profile() const { return m_profile; }
    QTableWidget* capability() const { return m_capability; }
    QLabel* violations() const { return m_violations; }
    /// The small multiples, one per point.
    const std::vector<plot::Chart*>& multiples() const { return m_multiples; }

private:
    /// Object names, wrapping and the minimum sizes that keep the window within 1280 px.
    void setUpWidgets();
    /// The capability table: statistic, value, interval; only the first column stretches.
    void setUpCapabilityTable();
    /// The point bar above the tabs: control charts, distribution, part profile, small multiples.
    void buildLayout();
    void fillPointChoice();
    void showMultiples();

    std::vector<storage::MeasurementRow> m_rows;
    std::vector<runtime::PointReport> m_points;
    std::vector<std::pair<std::int64_t, std::int64_t>> m_parts;  ///< (run, part) in production order
    QTabWidget* m_tabs;
    QLabel* m_pointLabel;
    QComboBox* m_point;
    QLabel* m_summary;
    plot::Chart* m_location;
    plot::Chart* m_spread;
    QLabel* m_violations;
    QString m_adaptationsError;
    plot::Chart* m_histogram;
    QTableWidget* m_capability;
    QLabel* m_partLabel;
    QSpinBox* m_part;
    QLabel* m_partName;
    plot::Chart* m_profile;
    QWidget* m_multiplesHost;
    QGridLayout* m_multiplesGrid;
    std::vector<plot::Chart*> m_multiples;
};

}  // namespace tt::ui
