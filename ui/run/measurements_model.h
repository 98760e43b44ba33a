#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/ports/history_store.h"

namespace tt::ui {

/// The measured parts of one run, a row per part and control point: part, point, x, measured,
/// nominal, deviation, accepted/rejected with the reason, and the correction that part received.
class MeasurementsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Part, Point, X, Measured, Nominal, Deviation, Verdict, Reason, Applied, ColumnCount };

    explicit MeasurementsModel(QObject* parent = nullptr);

    /// Shows `parts` (all, or only the points that were rejected or not measured).
    void setParts(std::vector<core::StoredPart> parts, bool onlyProblems);
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    /// Rejected or unmeasured values among all rows.
    int problemCount() const { return m_problems; }

private:
    struct Row {
        qint64 part = 0;
        core::PointMeasurementRecord point;
        std::optional<double> applied;
    };
    std::vector<Row> m_rows;
    int m_problems = 0;
};

}  // namespace tt::ui
