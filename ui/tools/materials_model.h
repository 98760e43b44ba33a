#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/model/tool_stiffness.h"

namespace tt::ui {

/// The materials list with Young's modulus, editable in place. Edits are not kept here: the
/// model asks (materialEdited) and the page stores them through the tool store, then reloads.
class MaterialsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Name, Modulus, ColumnCount };

    explicit MaterialsModel(QObject* parent = nullptr);
    void setMaterials(std::vector<core::Material> materials);
    const std::vector<core::Material>& materials() const { return m_materials; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// Parses the new name or modulus (MPa, ',' accepted) and emits materialEdited; refuses
    /// text that is not a number with editRefused.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

signals:
    /// The material `previousName` should become `material` (a rename when the names differ).
    void materialEdited(const QString& previousName, const core::Material& material);
    void editRefused(const QString& reason);

private:
    std::vector<core::Material> m_materials;
};

}  // namespace tt::ui
