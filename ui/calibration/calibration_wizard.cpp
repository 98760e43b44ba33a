#include "ui/calibration/calibration_wizard.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tt::ui {

CalibrationWizard::CalibrationWizard(const QString& objectName, QWidget* parent) : QWizard(parent) {
    setObjectName(objectName);
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnStartPage, true);
}

void CalibrationWizard::retranslate() {
    setWindowTitle(titleText());
    setButtonText(QWizard::BackButton, tr("< Back"));
    setButtonText(QWizard::NextButton, tr("Next >"));
    setButtonText(QWizard::FinishButton, tr("Finish"));
    setButtonText(QWizard::CancelButton, tr("Cancel"));
    for (int id : pageIds())
        if (auto* p = qobject_cast<CalibrationWizardPage*>(page(id))) p->retranslate();
}

void CalibrationWizard::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWizard::changeEvent(event);
}

void layOutCapturePage(QWizardPage* page, QVBoxLayout* left, QWidget* table, const QList<QWidget*>& rowButtons,
                       QWidget* chart, QWidget* message) {
    left->addWidget(table, 1);
    auto* buttons = new QHBoxLayout;
    for (QWidget* b : rowButtons)
        buttons->addWidget(b);
    left->addLayout(buttons);
    auto* body = new QHBoxLayout;
    body->addLayout(left, 2);
    body->addWidget(chart, 3);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(body, 1);
    layout->addWidget(message);
}

int selectedRowOrLast(const QTableWidget* table, int count) {
    const QList<QTableWidgetItem*> selected = table->selectedItems();
    const int row = selected.isEmpty() ? -1 : selected.front()->row();
    return row >= 0 && row < count ? row : count - 1;
}

QLabel* wrappedLabel(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    return label;
}

void markProblem(QLabel* label, bool problem) {
    label->setStyleSheet(problem ? QStringLiteral("color: #b71c1c; font-weight: bold;") : QString());
}

void markVerdict(QLabel* label, bool passed) {
    label->setStyleSheet(passed ? QStringLiteral("color: #1b5e20; font-weight: bold;")
                                : QStringLiteral("color: #b71c1c; font-weight: bold;"));
}

}  // namespace tt::ui
