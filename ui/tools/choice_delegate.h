#pragma once

#include <QList>
#include <QPair>
#include <QStyledItemDelegate>
#include <functional>

namespace tt::ui {

/// An item delegate that edits chosen columns with a combo box: `choices(index)` gives the
/// (shown text, value written with setData) pairs; other columns get the default editor. The
/// editors are sized for gloved hands (the style sheet's minimum heights).
class ChoiceDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using Choices = std::function<QList<QPair<QString, QString>>(const QModelIndex& index)>;

    ChoiceDelegate(QList<int> columns, Choices choices, QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;

private:
    QList<int> m_columns;
    Choices m_choices;
};

}  // namespace tt::ui
