#include "ui/tools/materials_model.h"

#include <cmath>

namespace tt::ui {

MaterialsModel::MaterialsModel(QObject* parent) : QAbstractTableModel(parent) {}

void MaterialsModel::setMaterials(std::vector<core::Material> materials) {
    beginResetModel();
    m_materials = std::move(materials);
    endResetModel();
}

int MaterialsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_materials.size());
}

int MaterialsModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MaterialsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    return section == Name ? tr("Material") : tr("Young's modulus E, MPa");
}

Qt::ItemFlags MaterialsModel::flags(const QModelIndex& index) const {
    return index.isValid() ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable : Qt::NoItemFlags;
}

QVariant MaterialsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const core::Material& m = m_materials.at(static_cast<std::size_t>(index.row()));
    if (role == Qt::TextAlignmentRole && index.column() == Modulus) return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    return index.column() == Name ? QString::fromStdString(m.name) : QString::number(m.youngsModulusMpa, 'g', 10);
}

bool MaterialsModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole) return false;
    core::Material m = m_materials.at(static_cast<std::size_t>(index.row()));
    const QString previous = QString::fromStdString(m.name);
    const QString text = value.toString().trimmed();
    if (index.column() == Name) {
        if (text.isEmpty()) {
            emit editRefused(tr("material: the name must not be empty"));
            return false;
        }
        m.name = text.toStdString();
    } else {
        bool ok = false;
        const double e = QString(text).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
        if (!ok || !std::isfinite(e) || e < core::kMinYoungsModulusMpa || e > core::kMaxYoungsModulusMpa) {
            emit editRefused(tr("Young's modulus E: '%1' must be a number between %2 and %3 MPa")
                                 .arg(text)
                                 .arg(core::kMinYoungsModulusMpa, 0, 'f', 0)
                                 .arg(core::kMaxYoungsModulusMpa, 0, 'f', 0));
            return false;
        }
        m.youngsModulusMpa = e;
    }
    emit materialEdited(previous, m);
    return true;
}

}  // namespace tt::ui
