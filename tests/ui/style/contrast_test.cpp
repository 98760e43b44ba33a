// Visible widgets (issue 17, item 8): on every page and tab, in English and in Russian, the text of every
// visible, enabled label, button, check box, line edit, combo box and spin box contrasts with its
// background by at least 4.5 : 1 (WCAG 2.1 success criterion 1.4.3, normal text), and the arrows of
// combo and spin boxes by at least 3 : 1 (criterion 1.4.11, graphical objects). Measured on PIXELS: the
// window is rendered, each widget's text area sampled: background = its most frequent colour, text = the
// pixel of highest contrast against it (tests/ui/support/contrast.h). Disabled widgets are exempt (1.4.3).
// The open list of a combo box: its highlighted item and a plain one, the same way.
// Screenshots: screenshots/terminal_combo_open_<en|ru>.png (window with the open list).
#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QRadioButton>
#include <QSpinBox>
#include <QStyleOptionComboBox>
#include <QStyleOptionSpinBox>
#include <QTabWidget>
#include <QTest>

#include "support/contrast.h"
#include "screenshots.h"
#include "support/terminal_window.h"
#include "ui/pages/process_page.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

constexpr double kTextRatio = 4.5;     // WCAG 2.1, 1.4.3 (AA), normal-size text
constexpr double kGraphicRatio = 3.0;  // WCAG 2.1, 1.4.11, graphical objects (arrows)

class Contrast : public test::TerminalWindowTest, public ::testing::WithParamInterface<const char*> {
protected:
    QString lang() const { return QString::fromLatin1(GetParam()); }

    /// `rect` (in `w`'s coordinates, clipped to what is visible of it) in the window's image coordinates.
    static QRect onWindow(QWidget* w, const QRect& rect) {
        const QRect visible = rect.intersected(w->visibleRegion().boundingRect());
        if (visible.isEmpty()) return {};
        return QRect(w->mapTo(w->window(), visible.topLeft()), visible.size());
    }

    void expectRatio(const QImage& image, QWidget* w, const QRect& rect, double minimum, const QString& what,
                     const QString& where) {
        const QRect r = onWindow(w, rect);
        if (r.width() < 4 || r.height() < 4) return;
        ++sampled;
        const test::RegionContrast c = test::sampleContrast(image, r);
        if (c.ratio < minimum)
            problems << QStringLiteral("%1: %2 of %3 '%4': %5 on %6 is %7 : 1 (needs %8)")
                            .arg(where, what, QString::fromLatin1(w->metaObject()->className()), w->objectName(),
                                 c.foreground.name(), c.background.name())
                            .arg(c.ratio, 0, 'f', 2)
                            .arg(minimum);
    }

    /// Samples every visible, enabled text widget of the window as the image shows it.
    void checkWindow(MainWindow& window, const QString& where) {
        for (int i = 0; i < 3; ++i)
            QApplication::processEvents();
        const QImage image = window.grab().toImage();
        for (QWidget* w : window.findChildren<QWidget*>()) {
            if (!w->isVisible() || !w->isEnabled() || w->window() != &window) continue;
            if (auto* label = qobject_cast<QLabel*>(w)) {
                if (label->text().trimmed().isEmpty() || !label->pixmap().isNull()) continue;
                expectRatio(image, w, label->contentsRect(), kTextRatio, QStringLiteral("text"), where);
            } else if (qobject_cast<QCheckBox*>(w) || qobject_cast<QRadioButton*>(w)) {
                auto* b = static_cast<QAbstractButton*>(w);
                if (b->text().isEmpty()) continue;
                QStyleOptionButton o;
                o.initFrom(b);
                o.text = b->text();
                const QRect text = b->style()->subElementRect(
                    qobject_cast<QCheckBox*>(w) ? QStyle::SE_CheckBoxContents : QStyle::SE_RadioButtonContents, &o, b);
                expectRatio(image, w, text, kTextRatio, QStringLiteral("text"), where);
            } else if (auto* b = qobject_cast<QAbstractButton*>(w)) {
                if (b->text().isEmpty()) continue;
                expectRatio(image, w, b->rect().adjusted(3, 3, -3, -3), kTextRatio, QStringLiteral("text"), where);
            } else if (auto* combo = qobject_cast<QComboBox*>(w)) {
                QStyleOptionComboBox o;
                o.initFrom(combo);
                o.editable = combo->isEditable();
                const QRect field =
                    combo->style()->subControlRect(QStyle::CC_ComboBox, &o, QStyle::SC_ComboBoxEditField, combo);
                const QRect arrow =
                    combo->style()->subControlRect(QStyle::CC_ComboBox, &o, QStyle::SC_ComboBoxArrow, combo);
                if (!combo->currentText().isEmpty())
                    expectRatio(image, w, field, kTextRatio, QStringLiteral("text"), where);
                expectRatio(image, w, arrow, kGraphicRatio, QStringLiteral("arrow"), where);
            } else if (auto* spin = qobject_cast<QAbstractSpinBox*>(w)) {
                QStyleOptionSpinBox o;
                o.initFrom(spin);
                o.buttonSymbols = spin->buttonSymbols();
                o.subControls = QStyle::SC_All;
                o.stepEnabled = QAbstractSpinBox::StepUpEnabled | QAbstractSpinBox::StepDownEnabled;
                if (auto* edit = spin->findChild<QLineEdit*>(); edit && !spin->text().isEmpty())
                    expectRatio(image, edit, edit->rect(), kTextRatio, QStringLiteral("text"), where);
                for (auto [control, name] :
                     {std::pair{QStyle::SC_SpinBoxUp, "up arrow"}, std::pair{QStyle::SC_SpinBoxDown, "down arrow"}}) {
                    const QRect r = spin->style()->subControlRect(QStyle::CC_SpinBox, &o, control, spin);
                    expectRatio(image, w, r, kGraphicRatio, QString::fromLatin1(name), where);
                }
            } else if (auto* edit = qobject_cast<QLineEdit*>(w)) {
                if (edit->text().isEmpty() || qobject_cast<QAbstractSpinBox*>(edit->parentWidget())) continue;
                expectRatio(image, w, edit->rect().adjusted(3, 3, -3, -3), kTextRatio, QStringLiteral("text"), where);
            }
        }
    }

    QStringList problems;
    int sampled = 0;
};

TEST_P(Contrast, TextAndArrowsOfEveryPageAndTab) {
    ASSERT_TRUE(language.apply(lang()));
    auto window = openWindow();
    for (Page* page : window->pages()) {
        window->showPage(page->id());
        QTabWidget* tabs = nullptr;
        if (auto* run = qobject_cast<RunPage*>(page)) tabs = run->tabs();
        if (auto* process = qobject_cast<ProcessPage*>(page)) tabs = process->tabs();
        for (int t = 0; t < (tabs ? tabs->count() : 1); ++t) {
            if (tabs) tabs->setCurrentIndex(t);
            checkWindow(*window, lang() + QStringLiteral(", ") + pageKey(page->id()) +
                                     (tabs ? QStringLiteral(" tab %1").arg(t) : QString()));
        }
        if (tabs) tabs->setCurrentIndex(0);
    }
    EXPECT_GT(sampled, 200) << "widgets sampled";
    EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
}

TEST_P(Contrast, TheOpenListOfAComboBoxShowsItsHighlightedItem) {
    ASSERT_TRUE(language.apply(lang()));
    auto window = openWindow();
    window->showPage(PageId::Run);
    auto* combo = window->findChild<QComboBox*>(QStringLiteral("speedCombo"));
    ASSERT_NE(combo, nullptr);
    ASSERT_GE(combo->count(), 3);
    combo->showPopup();
    QAbstractItemView* view = combo->view();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view->window()));
    const QModelIndex highlighted = view->model()->index(1, combo->modelColumn());
    const QModelIndex plain = view->model()->index(3, combo->modelColumn());
    view->setCurrentIndex(highlighted);  // the item under the finger
    view->selectionModel()->select(highlighted, QItemSelectionModel::ClearAndSelect);
    for (int i = 0; i < 3; ++i)
        QApplication::processEvents();
    const QImage list = view->viewport()->grab().toImage();
    const test::RegionContrast hi = test::sampleContrast(list, view->visualRect(highlighted).adjusted(2, 2, -2, -2));
    const test::RegionContrast lo = test::sampleContrast(list, view->visualRect(plain).adjusted(2, 2, -2, -2));
    EXPECT_GE(hi.ratio, kTextRatio) << "highlighted item: " << hi.foreground.name().toStdString() << " on "
                                    << hi.background.name().toStdString();
    EXPECT_GE(lo.ratio, kTextRatio) << "plain item: " << lo.foreground.name().toStdString() << " on "
                                    << lo.background.name().toStdString();
    EXPECT_NE(hi.background, lo.background) << "the highlighted item stands out";
    // The window with the open list, as the operator sees it.
    QImage shot = window->grab().toImage();
    QPainter painter(&shot);
    // Drawn under the combo box (the offscreen platform has no real screen positions to read).
    painter.drawPixmap(combo->mapTo(window.get(), QPoint(0, combo->height())), view->window()->grab());
    painter.end();
    EXPECT_TRUE(
        shot.save(QDir(test::screenshotDir()).filePath(QStringLiteral("terminal_combo_open_%1.png").arg(lang()))));
    combo->hidePopup();
}

INSTANTIATE_TEST_SUITE_P(Languages, Contrast, ::testing::Values("en", "ru"));

}  // namespace
}  // namespace tt::ui
