#pragma once

#include <QString>

class QWidget;

namespace tt::ui {

/// Everything the UI asks the user through a modal dialog goes through this interface, so
/// tests answer with a scripted prompt and never block on a dialog.
class Prompt {
public:
    enum class Answer { Yes, No, Cancel };

    virtual ~Prompt() = default;
    /// A yes/no (optionally cancel) question.
    virtual Answer ask(QWidget* parent, const QString& title, const QString& question, bool withCancel = false) = 0;
    /// Information the user acknowledges (rich text allowed).
    virtual void inform(QWidget* parent, const QString& title, const QString& text) = 0;
    /// A warning or error the user acknowledges.
    virtual void warn(QWidget* parent, const QString& title, const QString& text) = 0;
    /// A file to open; empty when cancelled. `filter` as in QFileDialog ("CSV files (*.csv)").
    virtual QString openFileName(QWidget* parent, const QString& title, const QString& filter) = 0;
    /// A file to write; empty when cancelled.
    virtual QString saveFileName(QWidget* parent, const QString& title, const QString& suggestedName,
                                 const QString& filter) = 0;
};

/// The real dialogs: QMessageBox and QFileDialog.
class DialogPrompt final : public Prompt {
public:
    Answer ask(QWidget* parent, const QString& title, const QString& question, bool withCancel) override;
    void inform(QWidget* parent, const QString& title, const QString& text) override;
    void warn(QWidget* parent, const QString& title, const QString& text) override;
    QString openFileName(QWidget* parent, const QString& title, const QString& filter) override;
    QString saveFileName(QWidget* parent, const QString& title, const QString& suggestedName,
                         const QString& filter) override;
};

}  // namespace tt::ui
