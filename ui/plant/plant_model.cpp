#include "ui/plant/plant_model.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <algorithm>

namespace tt::ui {

namespace {

const QColor kGoodFill(200, 230, 201);
const QColor kWarnFill(255, 224, 178);
const QColor kBadFill(255, 205, 210);
const QColor kIdleFill(230, 233, 237);

/// Capability at or above 1.33 is capable, below 1.00 is not (Montgomery, 6th ed., Table 8.2).
constexpr double kCapable = 1.33;
constexpr double kIncapable = 1.00;

QString localTime(const QDateTime& utc) {
    const QDateTime local = utc.toLocalTime();
    return local.date() == QDate::currentDate() ? local.toString(QStringLiteral("HH:mm"))
                                                : local.toString(QStringLiteral("dd.MM HH:mm"));
}

}  // namespace

PlantModel::PlantModel(QObject* parent) : QAbstractTableModel(parent) {}

void PlantModel::setOverview(const runtime::PlantOverview& overview) {
    beginResetModel();
    m_overview = overview;
    m_points = 0;
    for (const runtime::PlantMachine& m : m_overview.machines)
        for (const runtime::PlantPointCapability& p : m.points)
            m_points = std::max(m_points, p.pointIndex + 1);
    endResetModel();
}

QString PlantModel::machineAt(int row) const {
    if (row < 0 || row >= static_cast<int>(m_overview.machines.size())) return {};
    return QString::fromStdString(m_overview.machines[static_cast<std::size_t>(row)].machine);
}

int PlantModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_overview.machines.size());
}

int PlantModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : kFirstPointColumn + m_points;
}

QString PlantModel::stateText(const runtime::PlantMachine& m) {
    const QString last = m.lastPartAt ? localTime(*m.lastPartAt) : QString();
    switch (m.state) {
        case runtime::MachineState::Running:
            return tr("running");
        case runtime::MachineState::Offline:
            return last.isEmpty() ? tr("offline") : tr("offline, last part %1").arg(last);
        case runtime::MachineState::Idle:
            break;
    }
    return last.isEmpty() ? tr("idle") : tr("idle, last part %1").arg(last);
}

const runtime::PlantPointCapability* PlantModel::point(const runtime::PlantMachine& m, int column) const {
    const int index = column - kFirstPointColumn;
    for (const runtime::PlantPointCapability& p : m.points)
        if (p.pointIndex == index) return &p;
    return nullptr;
}

QVariant PlantModel::cellText(const runtime::PlantMachine& m, int column) const {
    switch (column) {
        case Machine:
            return QString::fromStdString(m.machine);
        case State:
            return stateText(m);
        case Backlog:
            return m.backlogParts ? QString::number(*m.backlogParts) : QStringLiteral("—");
        case Today:
            return QStringLiteral("%1 / %2 / %3").arg(m.today.good).arg(m.today.rework).arg(m.today.scrap);
        case Alarms:
            return m.openAlarmCount > 0 ? QString::number(m.openAlarmCount) : QStringLiteral("—");
        default:
            break;
    }
    const runtime::PlantPointCapability* p = point(m, column);
    if (!p || !p->cpk) return QStringLiteral("—");
    QString text = QString::number(*p->cpk, 'f', 2);
    if (const std::optional<double> change = p->change())
        text += QStringLiteral(" %1%2").arg(*change >= 0 ? QStringLiteral("▲") : QStringLiteral("▼"),
                                            QString::number(std::abs(*change), 'f', 2));
    return text;
}

QVariant PlantModel::cellColour(const runtime::PlantMachine& m, int column) const {
    switch (column) {
        case State:
            return m.state == runtime::MachineState::Running   ? kGoodFill
                   : m.state == runtime::MachineState::Offline ? kBadFill
                                                      : kIdleFill;
        case Backlog:
            return m.journalNearFull ? kBadFill : (m.backlogParts && *m.backlogParts > 0 ? kWarnFill : QVariant());
        case Today:
            return m.today.scrap > 0 ? kBadFill : (m.today.rework > 0 ? kWarnFill : QVariant());
        case Alarms:
            return m.openAlarmCount > 0 ? kWarnFill : QVariant();
        case Machine:
            return QVariant();
        default:
            break;
    }
    const runtime::PlantPointCapability* p = point(m, column);
    if (!p || !p->cpk) return QVariant();
    return *p->cpk < kIncapable ? kBadFill : (*p->cpk < kCapable ? kWarnFill : kGoodFill);
}

QVariant PlantModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const runtime::PlantMachine& m = m_overview.machines[static_cast<std::size_t>(index.row())];
    switch (role) {
        case Qt::DisplayRole:
            return cellText(m, index.column());
        case Qt::BackgroundRole: {
            const QVariant colour = cellColour(m, index.column());
            return colour.isValid() ? QVariant(QBrush(colour.value<QColor>())) : QVariant();
        }
        case Qt::ForegroundRole:
            return QBrush(QColor(31, 42, 54));
        case Qt::TextAlignmentRole:
            return index.column() == Machine || index.column() == State
                       ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                       : QVariant(Qt::AlignCenter);
        case Qt::FontRole:
            if (index.column() == Machine) {
                QFont bold;
                bold.setBold(true);
                return bold;
            }
            return {};
        case Qt::ToolTipRole:
            if (index.column() == Alarms && !m.openAlarms.empty()) {
                QStringList lines;
                for (const storage::PlantAlarm& a : m.openAlarms)
                    lines << QString::fromStdString(a.message);
                return lines.join(QLatin1Char('\n'));
            }
            if (const runtime::PlantPointCapability* p = point(m, index.column()))
                return tr("Cpk of the last %1 parts; %2 parts before: %3")
                    .arg(p->count)
                    .arg(p->countBefore)
                    .arg(p->cpkBefore ? QString::number(*p->cpkBefore, 'f', 2) : QStringLiteral("—"));
            return {};
        default:
            return {};
    }
}

QVariant PlantModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Machine:
            return tr("Machine");
        case State:
            return tr("State");
        case Backlog:
            return tr("Kept on\nterminal");
        case Today:
            return tr("Today\ngood / rework / scrap");
        case Alarms:
            return tr("Alarms");
        default:
            return tr("Cpk\npoint %1").arg(section - kFirstPointColumn + 1);
    }
}

}  // namespace tt::ui
