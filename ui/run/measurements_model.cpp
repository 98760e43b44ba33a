#include "ui/run/measurements_model.h"

#include "ui/run/notice_text.h"

#include <QBrush>
#include <QColor>
#include <QLocale>

namespace tt::ui {

MeasurementsModel::MeasurementsModel(QObject* parent) : QAbstractTableModel(parent) {}

void MeasurementsModel::setParts(std::vector<core::StoredPart> parts, bool onlyProblems) {
    beginResetModel();
    m_rows.clear();
    m_problems = 0;
    for (const core::StoredPart& part : parts) {
        if (!part.measurement) continue;
        for (const core::PointMeasurementRecord& p : part.measurement->points) {
            const bool problem = !p.accepted;
            if (problem) ++m_problems;
            if (onlyProblems && !problem) continue;
            Row row{part.partNumber, p, std::nullopt};
            for (const core::PointCorrectionRecord& c : part.corrections)
                if (c.pointIndex == p.pointIndex) row.applied = c.appliedMm;
            m_rows.push_back(std::move(row));
        }
    }
    endResetModel();
}

int MeasurementsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int MeasurementsModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MeasurementsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= static_cast<int>(m_rows.size())) return {};
    const Row& r = m_rows[static_cast<std::size_t>(index.row())];
    const QLocale locale;
    if (role == Qt::ForegroundRole && !r.point.accepted) return QBrush(QColor(198, 40, 40));
    if (role == Qt::ToolTipRole && index.column() == Reason && !r.point.reason.empty())
        return r.point.rejection ? noticeText(r.point.rejection) : QString::fromStdString(r.point.reason);
    if (role == Qt::TextAlignmentRole)
        return index.column() == Reason || index.column() == Verdict ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                                                                     : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Part:
            return r.part;
        case Point:
            return r.point.pointIndex + 1;
        case X:
            return locale.toString(r.point.zMm, 'f', 1);
        case Measured:
            return r.point.measuredMm ? locale.toString(*r.point.measuredMm, 'f', 3) : tr("—");
        case Nominal:
            return locale.toString(r.point.nominalMm, 'f', 3);
        case Deviation:
            return r.point.measuredMm ? locale.toString(*r.point.measuredMm - r.point.nominalMm, 'f', 3) : tr("—");
        case Verdict:
            return r.point.accepted ? tr("accepted") : r.point.measuredMm ? tr("rejected") : tr("not measured");
        case Reason:
            return r.point.rejection ? noticeText(r.point.rejection) : QString::fromStdString(r.point.reason);
        case Applied:
            return r.applied ? locale.toString(*r.applied, 'f', 4) : tr("—");
        default:
            return {};
    }
}

QVariant MeasurementsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
        case Part:
            return tr("Part");
        case Point:
            return tr("Point");
        case X:
            return tr("x, mm");
        case Measured:
            return tr("Measured, mm");
        case Nominal:
            return tr("Nominal, mm");
        case Deviation:
            return tr("Deviation, mm");
        case Verdict:
            return tr("Verdict");
        case Reason:
            return tr("Reason");
        case Applied:
            return tr("Correction, mm");
        default:
            return {};
    }
}

}  // namespace tt::ui
