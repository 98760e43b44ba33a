#pragma once

#include <QWizard>
#include <QWizardPage>

class QLabel;
class QTableWidget;
class QVBoxLayout;

namespace tt::ui {

/// A page of a calibration wizard: it sets its texts in retranslate(), which the wizard calls
/// when it is built and on every language switch.
class CalibrationWizardPage : public QWizardPage {
    Q_OBJECT
public:
    using QWizardPage::QWizardPage;
    virtual void retranslate() = 0;

protected:
    /// Whether this page is the one its wizard shows. A page's poll timer keeps running after Next
    /// (QWizard calls cleanupPage only on Back); it must not take the procedure's events meant for the
    /// page shown (a verification's result on the next page).
    bool isShown() const { return wizard() && wizard()->currentPage() == this; }
};

/// What both calibration wizards (probe linearisation, k_p from known loads) share: the
/// terminal's wizard style, translated buttons, and pages that follow the language switch.
class CalibrationWizard : public QWizard {
    Q_OBJECT
public:
    /// Sets the title and the buttons and lets every page set its texts.
    void retranslate();

protected:
    CalibrationWizard(const QString& objectName, QWidget* parent);
    /// The window title in the current language.
    virtual QString titleText() const = 0;
    void changeEvent(QEvent* event) override;
};

/// The layout of a capture page: `left` (filled by the caller with what goes above the points)
/// then the points table and the buttons that act on its selected row side by side, the chart to
/// the right, the message below both.
void layOutCapturePage(QWizardPage* page, QVBoxLayout* left, QWidget* table, const QList<QWidget*>& rowButtons,
                       QWidget* chart, QWidget* message);
/// The row selected in a points table of `count` rows, or the last row when none is (−1: empty).
int selectedRowOrLast(const QTableWidget* table, int count);
/// A label that wraps its text (instructions, results).
QLabel* wrappedLabel(QWidget* parent);
/// Shows `label` in the problem colour (bold dark red) or in the normal one.
void markProblem(QLabel* label, bool problem);
/// Shows a verdict in `label`: bold dark green when it passed, bold dark red when not.
void markVerdict(QLabel* label, bool passed);

}  // namespace tt::ui
