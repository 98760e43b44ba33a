#pragma once

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QMainWindow>
#include <QPushButton>
#include <QStackedWidget>
#include <QStringList>
#include <QWidget>

namespace tt::ui::test {

/// The terminal's screen, px.
inline constexpr int kScreenWidth = 1280;
inline constexpr int kScreenHeight = 800;

/// What of `window` does not fit the 1280 x 800 screen: its size and its minimum size; `where` names
/// the state ("ru, calibration, probe wizard page 3").
inline QStringList sizeProblems(QWidget& window, const QString& where) {
    QApplication::processEvents();
    QStringList problems;
    const QSize size = window.size();
    const QSize need = window.minimumSizeHint().expandedTo(window.minimumSize());
    if (size.width() > kScreenWidth || size.height() > kScreenHeight)
        problems << QStringLiteral("%1: the window is %2 x %3 px").arg(where).arg(size.width()).arg(size.height());
    if (need.width() > kScreenWidth || need.height() > kScreenHeight) {
        QString widest;
        if (auto* main = qobject_cast<QMainWindow*>(&window))
            if (auto* stack = main->centralWidget()->findChild<QStackedWidget*>())
                for (int i = 0; i < stack->count(); ++i)
                    widest += QStringLiteral(" %1 %2x%3;")
                                  .arg(stack->widget(i)->metaObject()->className())
                                  .arg(stack->widget(i)->minimumSizeHint().width())
                                  .arg(stack->widget(i)->minimumSizeHint().height());
        problems << QStringLiteral("%1: the window needs %2 x %3 px (pages:%4)")
                        .arg(where)
                        .arg(need.width())
                        .arg(need.height())
                        .arg(widest);
    }
    return problems;
}

/// Buttons and one-line labels under `root` narrower than their text (cut off), and widgets that reach
/// beyond the window's right or bottom edge.
inline QStringList cutOffProblems(QWidget* root, const QString& where) {
    QStringList problems;
    QWidget* window = root->window();
    const QRect screen(QPoint(0, 0), window->size());
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!w->isVisible() || w->width() <= 0) continue;
        const QString name =
            QStringLiteral("%1 '%2'").arg(QString::fromLatin1(w->metaObject()->className()), w->objectName());
        QString text;
        int need = 0;
        if (auto* label = qobject_cast<QLabel*>(w)) {
            if (!label->wordWrap() && !label->text().isEmpty() && label->textFormat() != Qt::RichText &&
                !label->text().contains(QLatin1Char('<')))
                need = label->sizeHint().width(), text = label->text();
        } else if (auto* button = qobject_cast<QAbstractButton*>(w)) {
            if (!button->text().isEmpty()) need = button->sizeHint().width(), text = button->text();
        } else if (auto* edit = qobject_cast<QLineEdit*>(w);
                   edit && qobject_cast<QAbstractSpinBox*>(w->parentWidget())) {
            // A spin box's number and unit beside its arrows: the text must fit its edit field.
            text = edit->text();
            const int fits = edit->fontMetrics().horizontalAdvance(text) + 4;  // the edit's 2 px text margins
            if (fits > edit->width() + 1)
                problems << QStringLiteral("%1: cut off \"%2\" in the spin box '%3' (%4 px of %5 px)")
                                .arg(where, text, w->parentWidget()->objectName())
                                .arg(edit->width())
                                .arg(fits);
            continue;
        }
        if (need > w->width() + 1)
            problems << QStringLiteral("%1: cut off \"%2\" in %3 (%4 px of %5 px)")
                            .arg(where, text, name)
                            .arg(w->width())
                            .arg(need);
        bool scrolled = false;  // inside a scroll area: reached by scrolling
        for (QWidget* p = w->parentWidget(); p && !scrolled; p = p->parentWidget())
            scrolled = qobject_cast<QAbstractScrollArea*>(p) != nullptr;
        const QRect onWindow(w->mapTo(window, QPoint(0, 0)), w->size());
        if (!text.isEmpty() && !scrolled && !screen.contains(onWindow))
            problems << QStringLiteral("%1: \"%2\" in %3 reaches beyond the window").arg(where, text, name);
    }
    return problems;
}

/// Visible widgets under `root` that overlap a visible sibling placed by the same layout (a layout squeezed
/// below what its word-wrapped texts need draws them over each other).
inline QStringList overlapProblems(QWidget* root, const QString& where) {
    QStringList problems;
    QList<QWidget*> parents = root->findChildren<QWidget*>();
    parents.prepend(root);
    for (QWidget* parent : parents) {
        if (!parent->isVisible() || !parent->layout()) continue;
        QList<QWidget*> placed;
        for (QWidget* child : parent->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (child->isVisible() && !child->isWindow()) placed << child;
        // Widgets of nested layouts are direct children of `parent` too: every pair is checked.
        for (int i = 0; i < placed.size(); ++i)
            for (int j = i + 1; j < placed.size(); ++j) {
                const QRect both = placed[i]->geometry().intersected(placed[j]->geometry());
                if (both.width() > 1 && both.height() > 1)
                    problems << QStringLiteral("%1: %2 '%3' and %4 '%5' overlap by %6 x %7 px")
                                    .arg(where, QString::fromLatin1(placed[i]->metaObject()->className()),
                                         placed[i]->objectName(),
                                         QString::fromLatin1(placed[j]->metaObject()->className()),
                                         placed[j]->objectName())
                                    .arg(both.width())
                                    .arg(both.height());
            }
    }
    return problems;
}

/// The touch target's least height, px: about 10 mm on the terminal's 15" 1280 x 800 panel (0.24 mm a
/// pixel), near WCAG 2.1's 44 px (success criterion 2.5.5) and wide enough for a gloved finger.
inline constexpr int kTouchTargetPx = 40;

/// Visible, enabled push buttons, combo boxes, spin boxes and line edits under `root` lower than a touch
/// target (kTouchTargetPx).
inline QStringList touchTargetProblems(QWidget* root, const QString& where) {
    QStringList problems;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!w->isVisible() || !w->isEnabled()) continue;
        const bool target = qobject_cast<QPushButton*>(w) || qobject_cast<QComboBox*>(w) ||
                            qobject_cast<QAbstractSpinBox*>(w) ||
                            (qobject_cast<QLineEdit*>(w) && !qobject_cast<QAbstractSpinBox*>(w->parentWidget()) &&
                             !qobject_cast<QComboBox*>(w->parentWidget()));
        if (target && w->height() < kTouchTargetPx)
            problems << QStringLiteral("%1: %2 '%3' is %4 px high (a touch target needs %5 px)")
                            .arg(where, QString::fromLatin1(w->metaObject()->className()), w->objectName())
                            .arg(w->height())
                            .arg(kTouchTargetPx);
    }
    return problems;
}

}  // namespace tt::ui::test
