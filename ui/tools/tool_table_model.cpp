#include "ui/tools/tool_table_model.h"

#include <QBrush>
#include <QColor>
#include <QDate>
#include <QFont>
#include <QUndoCommand>
#include <QUndoStack>
#include <stdexcept>

namespace tt::ui {

bool ToolRow::pending() const {
    if (!stored) return !removed;
    return removed || !core::diffTool(*stored, edited).empty();
}

/// Sets one row from `before` to `after` (edits, removals, imported replacements).
class ToolRowCommand : public QUndoCommand {
public:
    ToolRowCommand(ToolTableModel* model, int row, ToolRow before, ToolRow after, const QString& text,
                   QUndoCommand* parent = nullptr)
        : QUndoCommand(text, parent),
          m_model(model),
          m_row(row),
          m_before(std::move(before)),
          m_after(std::move(after)) {}
    void redo() override { m_model->setRow(m_row, m_after); }
    void undo() override { m_model->setRow(m_row, m_before); }

private:
    ToolTableModel* m_model;
    int m_row;
    ToolRow m_before;
    ToolRow m_after;
};

/// Appends a new row (always the last one, so undo drops the last row).
class AddToolCommand : public QUndoCommand {
public:
    AddToolCommand(ToolTableModel* model, ToolRow row, const QString& text, QUndoCommand* parent = nullptr)
        : QUndoCommand(text, parent), m_model(model), m_row(std::move(row)) {}
    void redo() override { m_model->appendRow(m_row); }
    void undo() override { m_model->dropLastRow(); }

private:
    ToolTableModel* m_model;
    ToolRow m_row;
};

namespace {

core::ToolField fieldOf(int column) {
    return core::allToolFields().at(static_cast<std::size_t>(column));
}

bool isNumeric(int column) {
    switch (column) {
        case ToolTableModel::Diameter:
        case ToolTableModel::Width:
        case ToolTableModel::Height:
        case ToolTableModel::Overhang:
        case ToolTableModel::YoungsModulus:
        case ToolTableModel::MeasuredStiffness:
        case ToolTableModel::CurrentToForceGain:
        case ToolTableModel::ComputedStiffness:
        case ToolTableModel::Slenderness:
            return true;
        default:
            return false;
    }
}

const QColor kPending(0xff, 0xf0, 0xb3);
const QColor kProblem(0xfd, 0xd8, 0xd4);
const QColor kRemoved(0xd5, 0xd9, 0xde);
const QColor kComputed(0xee, 0xf1, 0xf4);

}  // namespace

ToolTableModel::ToolTableModel(QObject* parent) : QAbstractTableModel(parent), m_undo(new QUndoStack(this)) {
    connect(m_undo, &QUndoStack::indexChanged, this, &ToolTableModel::pendingChanged);
}

QString ToolTableModel::columnTitle(int column) {
    switch (column) {
        case Id:
            return tr("Tool");
        case Name:
            return tr("Name");
        case Section:
            return tr("Section");
        case Diameter:
            return tr("d, mm");
        case Width:
            return tr("b, mm");
        case Height:
            return tr("h, mm");
        case Overhang:
            return tr("Overhang l, mm");
        case Material:
            return tr("Material");
        case YoungsModulus:
            return tr("E, MPa");
        case MeasuredStiffness:
            return tr("Measured k, N/mm");
        case MeasuredOn:
            return tr("Measured on");
        case MeasuredBy:
            return tr("Measured by");
        case CurrentToForceGain:
            return tr("k_p, N/A");
        case ComputedStiffness:
            return tr("k = 3EI/l³, N/mm");
        case Slenderness:
            return tr("l/d");
        default:
            return {};
    }
}

void ToolTableModel::load(const std::vector<core::ToolRecord>& stored, const std::vector<core::Material>& materials) {
    beginResetModel();
    m_rows.clear();
    for (const core::ToolRecord& t : stored)
        m_rows.push_back({t, t, false});
    m_materials = materials;
    endResetModel();
    m_undo->clear();
    emit pendingChanged();
}

void ToolTableModel::setMaterials(const std::vector<core::Material>& materials) {
    m_materials = materials;
    if (!m_rows.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

int ToolTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int ToolTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ToolTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Horizontal && role == Qt::DisplayRole) return columnTitle(section);
    if (orientation == Qt::Horizontal && role == Qt::ToolTipRole && section == ComputedStiffness)
        return tr("Computed from the section, the overhang and E; a measured stiffness overrides it");
    if (orientation == Qt::Vertical && role == Qt::DisplayRole) return section + 1;
    return {};
}

Qt::ItemFlags ToolTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const ToolRow& r = m_rows.at(static_cast<std::size_t>(index.row()));
    if (r.removed || index.column() >= ComputedStiffness) return f;
    const bool round = r.edited.section.shape == core::SectionShape::Round;
    switch (index.column()) {
        case Diameter:
            return round ? f | Qt::ItemIsEditable : f;
        case Width:
        case Height:
            return round ? f : f | Qt::ItemIsEditable;
        case MeasuredOn:
        case MeasuredBy:
            return r.edited.measured ? f | Qt::ItemIsEditable : f;
        default:
            return f | Qt::ItemIsEditable;
    }
}

QVariant ToolTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const ToolRow& r = m_rows.at(static_cast<std::size_t>(index.row()));
    const int column = index.column();
    const bool editableField = column < ComputedStiffness;
    const bool cellPending = editableField && !r.removed &&
                             (!r.stored || core::toolFieldText(*r.stored, fieldOf(column)) !=
                                               core::toolFieldText(r.edited, fieldOf(column)));
    switch (role) {
        case Qt::DisplayRole:
            return displayText(r, column);
        case Qt::EditRole:
            if (!editableField) return {};
            return QString::fromStdString(core::toolFieldText(r.edited, fieldOf(column)));
        case Qt::TextAlignmentRole:
            return isNumeric(column) ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                                     : QVariant(Qt::AlignLeft | Qt::AlignVCenter);
        case Qt::BackgroundRole:
            return background(index, cellPending);
        case Qt::FontRole:
            if (r.removed) {
                QFont f;
                f.setStrikeOut(true);
                return f;
            }
            return {};
        case Qt::ToolTipRole:
            return toolTip(index, cellPending);
        case PendingRole:
            return cellPending || (r.removed && r.stored.has_value());
        case ProblemRole:
            return !r.removed && !rowProblems(index.row()).isEmpty();
        default:
            return {};
    }
}

QString ToolTableModel::displayText(const ToolRow& r, int column) const {
    if (column == Section) return r.edited.section.shape == core::SectionShape::Round ? tr("round") : tr("rectangular");
    if (column == ComputedStiffness) {
        try {
            return QString::number(core::computedStiffnessNPerMm(r.edited), 'f', 0);
        } catch (const std::invalid_argument&) {
            return QStringLiteral("—");
        }
    }
    if (column == Slenderness) {
        try {
            return QString::number(core::slendernessRatio(r.edited), 'f', 1);
        } catch (const std::invalid_argument&) {
            return QStringLiteral("—");
        }
    }
    return QString::fromStdString(core::toolFieldText(r.edited, fieldOf(column)));
}

QVariant ToolTableModel::background(const QModelIndex& index, bool cellPending) const {
    const ToolRow& r = m_rows.at(static_cast<std::size_t>(index.row()));
    if (r.removed) return QBrush(kRemoved);
    if (index.column() >= ComputedStiffness || !(flags(index) & Qt::ItemIsEditable)) return QBrush(kComputed);
    if (!rowProblems(index.row()).isEmpty()) return QBrush(kProblem);
    if (cellPending) return QBrush(kPending);
    return {};
}

QVariant ToolTableModel::toolTip(const QModelIndex& index, bool cellPending) const {
    const ToolRow& r = m_rows.at(static_cast<std::size_t>(index.row()));
    QStringList lines = rowProblems(index.row());
    if (r.removed) lines.prepend(tr("Removed when you apply the changes"));
    if (cellPending && r.stored)
        lines << tr("Applied value: %1")
                     .arg(QString::fromStdString(core::toolFieldText(*r.stored, fieldOf(index.column()))));
    return lines.isEmpty() ? QVariant() : QVariant(lines.join(QLatin1Char('\n')));
}

double ToolTableModel::modulusOf(const std::string& material) const {
    for (const core::Material& m : m_materials)
        if (m.name == material) return m.youngsModulusMpa;
    return 0.0;
}

bool ToolTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole || !(flags(index) & Qt::ItemIsEditable)) return false;
    const int row = index.row();
    const int column = index.column();
    ToolRow after = m_rows.at(static_cast<std::size_t>(row));
    const std::string text = value.toString().toStdString();
    try {
        if (column == Material && modulusOf(text) <= 0.0)
            throw std::invalid_argument("material '" + text + "' is not in the materials list (Materials tab)");
        const bool hadMeasurement = after.edited.measured.has_value();
        core::setToolField(after.edited, fieldOf(column), text);
        if (column == Material) after.edited.youngsModulusMpa = modulusOf(text);
        if (column == MeasuredStiffness && !hadMeasurement && after.edited.measured) {
            after.edited.measured->measuredOn = QDate::currentDate().toString(Qt::ISODate).toStdString();
            after.edited.measured->measuredBy = m_operator.toStdString();
        }
    } catch (const std::invalid_argument& e) {
        emit editRefused(row, column, QString::fromStdString(e.what()));
        return false;
    }
    const ToolRow& before = m_rows.at(static_cast<std::size_t>(row));
    if (core::diffTool(before.edited, after.edited).empty()) return true;
    m_undo->push(new ToolRowCommand(this, row, before, after,
                                    tr("%1 of %2").arg(columnTitle(column), QString::fromStdString(before.edited.id))));
    return true;
}

void ToolTableModel::setRow(int row, const ToolRow& value) {
    m_rows.at(static_cast<std::size_t>(row)) = value;
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    // A changed id can make another row a duplicate (or no longer one).
    if (!m_rows.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::BackgroundRole});
    emit pendingChanged();
}

void ToolTableModel::appendRow(const ToolRow& value) {
    const int row = rowCount();
    beginInsertRows({}, row, row);
    m_rows.push_back(value);
    endInsertRows();
    emit pendingChanged();
}

void ToolTableModel::dropLastRow() {
    const int row = rowCount() - 1;
    beginRemoveRows({}, row, row);
    m_rows.pop_back();
    endRemoveRows();
    emit pendingChanged();
}

QString ToolTableModel::nextFreeId() const {
    for (int n = 1;; ++n) {
        const QString id = QStringLiteral("T%1").arg(n);
        bool used = false;
        for (const ToolRow& r : m_rows)
            used = used || QString::fromStdString(r.edited.id) == id;
        if (!used) return id;
    }
}

int ToolTableModel::addTool() {
    core::ToolRecord tool = core::defaultTool(nextFreeId().toStdString());
    if (const double e = modulusOf(tool.material); e > 0.0) tool.youngsModulusMpa = e;
    m_undo->push(
        new AddToolCommand(this, {std::nullopt, tool, false}, tr("Add %1").arg(QString::fromStdString(tool.id))));
    return rowCount() - 1;
}

void ToolTableModel::removeTools(const QList<int>& rows) {
    QList<int> live;
    for (int row : rows)
        if (row >= 0 && row < rowCount() && !m_rows.at(static_cast<std::size_t>(row)).removed) live << row;
    if (live.isEmpty()) return;
    m_undo->beginMacro(live.size() == 1 ? tr("Remove %1").arg(QString::fromStdString(m_rows.at(live[0]).edited.id))
                                        : tr("Remove %1 tools").arg(live.size()));
    for (int row : live) {
        ToolRow after = m_rows.at(static_cast<std::size_t>(row));
        after.removed = true;
        m_undo->push(new ToolRowCommand(this, row, m_rows.at(static_cast<std::size_t>(row)), after, QString()));
    }
    m_undo->endMacro();
}

void ToolTableModel::replaceTool(int row, const core::ToolRecord& tool, const QString& label) {
    ToolRow after = m_rows.at(static_cast<std::size_t>(row));
    after.edited = tool;
    after.removed = false;
    m_undo->push(new ToolRowCommand(this, row, m_rows.at(static_cast<std::size_t>(row)), after, label));
}

void ToolTableModel::importTools(const std::vector<core::ToolRecord>& tools, const QString& label) {
    if (tools.empty()) return;
    m_undo->beginMacro(label);
    for (const core::ToolRecord& t : tools) {
        const int row = rowOfId(t.id);
        if (row >= 0)
            replaceTool(row, t, QString());
        else
            m_undo->push(new AddToolCommand(this, {std::nullopt, t, false}, QString()));
    }
    m_undo->endMacro();
}

int ToolTableModel::rowOfId(const std::string& id) const {
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (!m_rows[i].removed && m_rows[i].edited.id == id) return static_cast<int>(i);
    return -1;
}

std::vector<core::ToolRecord> ToolTableModel::currentTools() const {
    std::vector<core::ToolRecord> out;
    for (const ToolRow& r : m_rows)
        if (!r.removed) out.push_back(r.edited);
    return out;
}

int ToolTableModel::pendingCount() const {
    int n = 0;
    for (const ToolRow& r : m_rows)
        n += r.pending() ? 1 : 0;
    return n;
}

QStringList ToolTableModel::rowProblems(int row) const {
    QStringList out;
    const ToolRow& r = m_rows.at(static_cast<std::size_t>(row));
    if (r.removed) return out;
    for (const std::string& p : core::validateTool(r.edited))
        out << QString::fromStdString(p);
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (static_cast<int>(i) != row && !m_rows[i].removed && m_rows[i].edited.id == r.edited.id &&
            !r.edited.id.empty()) {
            out << tr("id: %1 is also used in row %2").arg(QString::fromStdString(r.edited.id)).arg(i + 1);
            break;
        }
    return out;
}

QStringList ToolTableModel::problems() const {
    QStringList out;
    for (int row = 0; row < rowCount(); ++row)
        for (const QString& p : rowProblems(row))
            out << QStringLiteral("%1: %2").arg(QString::fromStdString(m_rows[static_cast<std::size_t>(row)].edited.id),
                                                p);
    return out;
}

std::vector<storage::ToolEdit> ToolTableModel::pendingEdits() const {
    std::vector<storage::ToolEdit> edits;
    for (const ToolRow& r : m_rows) {
        if (!r.pending()) continue;
        if (r.removed) {
            if (r.stored) edits.push_back({r.stored->id, std::nullopt});
        } else {
            edits.push_back({r.stored ? std::optional<std::string>(r.stored->id) : std::nullopt, r.edited});
        }
    }
    return edits;
}

void ToolTableModel::markApplied(const std::vector<core::ToolRecord>& stored) {
    load(stored, m_materials);
}

void ToolTableModel::discard() {
    std::vector<core::ToolRecord> stored;
    for (const ToolRow& r : m_rows)
        if (r.stored) stored.push_back(*r.stored);
    load(stored, m_materials);
}

}  // namespace tt::ui
