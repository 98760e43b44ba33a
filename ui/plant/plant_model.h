#pragma once

#include <QAbstractTableModel>
#include <QString>

#include "runtime/reports/plant_report.h"

namespace tt::ui {

/// The machines of the plant overview as table rows: machine, state (with the last part's time when it is not
/// running), parts kept on its terminal, the day's good / rework / scrap parts, per control point the Cpk of the
/// last parts with its change against the ones before, and the open alarms. Cells are coloured by state, verdicts
/// and capability (Cpk below 1.00 red, below 1.33 amber, otherwise green).
class PlantModel : public QAbstractTableModel {
    Q_OBJECT
public:
    /// The fixed columns; the points' columns follow kFirstPointColumn.
    enum Column { Machine, State, Backlog, Today, Alarms, kFirstPointColumn };

    explicit PlantModel(QObject* parent = nullptr);

    /// Shows `overview` (its machines, by name).
    void setOverview(const runtime::PlantOverview& overview);
    const runtime::PlantOverview& overview() const { return m_overview; }
    /// The machine of row `row` (empty when out of range).
    QString machineAt(int row) const;
    /// The control points shown (the most any machine has).
    int pointColumns() const { return m_points; }

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    /// The state in the user's words ("running", "idle", "offline since 14:02").
    static QString stateText(const runtime::PlantMachine& machine);

private:
    QVariant cellText(const runtime::PlantMachine& m, int column) const;
    QVariant cellColour(const runtime::PlantMachine& m, int column) const;
    const runtime::PlantPointCapability* point(const runtime::PlantMachine& m, int column) const;

    runtime::PlantOverview m_overview;
    int m_points = 0;
};

}  // namespace tt::ui
