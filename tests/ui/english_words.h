#pragma once

#include <QAbstractButton>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QRegularExpression>
#include <QStringList>
#include <QWidget>

namespace tt::ui::test {

/// Texts `root` shows that hold an English word (two Latin letters in a row), each with where it is:
/// labels, buttons, group titles, progress texts, combo-box items and list items. `data` are names the
/// operator or the preset gave (a tool's name, a set-up's file name), not texts of the terminal.
inline QStringList englishIn(QWidget* root, const QStringList& data) {
    static const QRegularExpression latinWord(QStringLiteral("[A-Za-z]{2,}"));
    QStringList found;
    auto check = [&](const QWidget* w, QString text) {
        for (const QString& name : data)
            text.remove(name);
        if (text.contains(latinWord))
            found << QStringLiteral("\"%1\" in %2 '%3'")
                         .arg(text, QString::fromLatin1(w->metaObject()->className()), w->objectName());
    };
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(root)) continue;
        if (auto* label = qobject_cast<QLabel*>(w)) check(w, label->text());
        if (auto* button = qobject_cast<QAbstractButton*>(w)) check(w, button->text());
        if (auto* group = qobject_cast<QGroupBox*>(w)) check(w, group->title());
        if (auto* progress = qobject_cast<QProgressBar*>(w)) check(w, progress->text());
        if (auto* combo = qobject_cast<QComboBox*>(w))
            for (int i = 0; i < combo->count(); ++i)
                check(w, combo->itemText(i));
        if (auto* list = qobject_cast<QListWidget*>(w))
            for (int i = 0; i < list->count(); ++i)
                check(w, list->item(i)->text());
    }
    return found;
}

}  // namespace tt::ui::test
