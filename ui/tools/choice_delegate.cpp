#include "ui/tools/choice_delegate.h"

#include <QComboBox>

namespace tt::ui {

ChoiceDelegate::ChoiceDelegate(QList<int> columns, Choices choices, QObject* parent)
    : QStyledItemDelegate(parent), m_columns(std::move(columns)), m_choices(std::move(choices)) {}

QWidget* ChoiceDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                      const QModelIndex& index) const {
    if (!m_columns.contains(index.column())) return QStyledItemDelegate::createEditor(parent, option, index);
    auto* combo = new QComboBox(parent);
    combo->setObjectName(QStringLiteral("choiceEditor"));
    for (const auto& [text, value] : m_choices(index))
        combo->addItem(text, value);
    return combo;
}

void ChoiceDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* combo = qobject_cast<QComboBox*>(editor);
    if (!combo) {
        QStyledItemDelegate::setEditorData(editor, index);
        return;
    }
    const int at = combo->findData(index.data(Qt::EditRole).toString());
    combo->setCurrentIndex(at >= 0 ? at : 0);
}

void ChoiceDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const {
    auto* combo = qobject_cast<QComboBox*>(editor);
    if (!combo) {
        QStyledItemDelegate::setModelData(editor, model, index);
        return;
    }
    model->setData(index, combo->currentData().toString(), Qt::EditRole);
}

}  // namespace tt::ui
