#include "ui/prompt.h"

#include <QFileDialog>
#include <QMessageBox>

namespace tt::ui {

Prompt::Answer DialogPrompt::ask(QWidget* parent, const QString& title, const QString& question, bool withCancel) {
    QMessageBox::StandardButtons buttons = QMessageBox::Yes | QMessageBox::No;
    if (withCancel) buttons |= QMessageBox::Cancel;
    switch (QMessageBox::question(parent, title, question, buttons)) {
        case QMessageBox::Yes:
            return Answer::Yes;
        case QMessageBox::No:
            return Answer::No;
        default:
            return Answer::Cancel;
    }
}

void DialogPrompt::inform(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox::information(parent, title, text);
}

void DialogPrompt::warn(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox::warning(parent, title, text);
}

QString DialogPrompt::openFileName(QWidget* parent, const QString& title, const QString& filter) {
    return QFileDialog::getOpenFileName(parent, title, QString(), filter);
}

QString DialogPrompt::saveFileName(QWidget* parent, const QString& title, const QString& suggestedName,
                                   const QString& filter) {
    return QFileDialog::getSaveFileName(parent, title, suggestedName, filter);
}

}  // namespace tt::ui
