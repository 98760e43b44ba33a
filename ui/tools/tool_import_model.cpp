#include "ui/tools/tool_import_model.h"

#include <QBrush>
#include <QColor>

#include "ui/tools/tool_table_model.h"

namespace tt::ui {

ToolImportModel::ToolImportModel(QObject* parent) : QAbstractTableModel(parent) {}

QString ToolImportModel::choiceText(Choice choice) {
    return choice == Choice::TakeFile ? tr("Take from file") : tr("Keep table");
}

void ToolImportModel::setRows(const std::vector<core::ToolCsvRow>& rows, const ToolTableModel& table) {
    beginResetModel();
    m_rows.clear();
    for (const core::ToolCsvRow& csv : rows) {
        Row r;
        r.csv = csv;
        if (!csv.problems.empty()) {
            r.state = State::Invalid;
            for (const std::string& p : csv.problems)
                r.details << QString::fromStdString(p);
        } else if (const int existing = table.rowOfId(csv.tool.id); existing < 0) {
            r.state = State::New;
            r.choice = Choice::TakeFile;
        } else {
            for (const core::ToolFieldChange& c : core::diffTool(table.toolRow(existing).edited, csv.tool))
                r.details << QStringLiteral("%1: %2 → %3")
                                 .arg(QString::fromStdString(core::toolFieldKey(c.field)),
                                      c.before.empty() ? QStringLiteral("—") : QString::fromStdString(c.before),
                                      c.after.empty() ? QStringLiteral("—") : QString::fromStdString(c.after));
            r.state = r.details.isEmpty() ? State::Unchanged : State::Conflict;
        }
        m_rows.push_back(std::move(r));
    }
    endResetModel();
}

void ToolImportModel::setAllConflicts(Choice choice) {
    for (Row& r : m_rows)
        if (r.state == State::Conflict) r.choice = choice;
    if (!m_rows.empty()) emit dataChanged(index(0, Action), index(rowCount() - 1, Action));
}

std::vector<core::ToolRecord> ToolImportModel::toImport() const {
    std::vector<core::ToolRecord> out;
    for (const Row& r : m_rows)
        if (r.state == State::New || (r.state == State::Conflict && r.choice == Choice::TakeFile))
            out.push_back(r.csv.tool);
    return out;
}

int ToolImportModel::count(State state) const {
    int n = 0;
    for (const Row& r : m_rows)
        n += r.state == state ? 1 : 0;
    return n;
}

int ToolImportModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int ToolImportModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ToolImportModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Line:
            return tr("Line");
        case Id:
            return tr("Tool");
        case Status:
            return tr("In the table");
        case Details:
            return tr("Differences (table → file) or problems");
        case Action:
            return tr("Import");
        default:
            return {};
    }
}

Qt::ItemFlags ToolImportModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == Action && m_rows.at(static_cast<std::size_t>(index.row())).state == State::Conflict)
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant ToolImportModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const Row& r = m_rows.at(static_cast<std::size_t>(index.row()));
    if (role == Qt::BackgroundRole) {
        switch (r.state) {
            case State::New:
                return QBrush(QColor(0xe3, 0xf2, 0xe1));
            case State::Conflict:
                return QBrush(QColor(0xff, 0xf0, 0xb3));
            case State::Invalid:
                return QBrush(QColor(0xfd, 0xd8, 0xd4));
            case State::Unchanged:
                return {};
        }
    }
    if (role == Qt::EditRole && index.column() == Action)
        return r.choice == Choice::TakeFile ? QStringLiteral("file") : QStringLiteral("table");
    if (role == Qt::ToolTipRole && index.column() == Details) return r.details.join(QLatin1Char('\n'));
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Line:
            return r.csv.line;
        case Id:
            return QString::fromStdString(r.csv.tool.id);
        case Status:
            switch (r.state) {
                case State::New:
                    return tr("new");
                case State::Unchanged:
                    return tr("same");
                case State::Conflict:
                    return tr("different");
                case State::Invalid:
                    return tr("cannot be read");
            }
            return {};
        case Details:
            return r.details.join(QStringLiteral("; "));
        case Action:
            switch (r.state) {
                case State::New:
                    return tr("Add");
                case State::Unchanged:
                    return tr("Nothing to do");
                case State::Conflict:
                    return choiceText(r.choice);
                case State::Invalid:
                    return tr("Skipped");
            }
            return {};
        default:
            return {};
    }
}

bool ToolImportModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole || !(flags(index) & Qt::ItemIsEditable)) return false;
    Row& r = m_rows.at(static_cast<std::size_t>(index.row()));
    const QString text = value.toString();
    if (text == QStringLiteral("file"))
        r.choice = Choice::TakeFile;
    else if (text == QStringLiteral("table"))
        r.choice = Choice::KeepTable;
    else
        return false;
    emit dataChanged(index, index);
    return true;
}

}  // namespace tt::ui
