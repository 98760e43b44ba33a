#pragma once

#include "ui/page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tt::ui {

/// Operator and terminal settings: interface language, the operator's name (recorded with every
/// change the operator applies), and where the run history is stored.
class SettingsPage : public Page {
    Q_OBJECT
public:
    explicit SettingsPage(AppContext& context, QWidget* parent = nullptr);
    QString title() const override;
    void retranslate() override;

private:
    void fillLanguages();
    void onLanguageChosen(int index);
    void onOperatorEdited();

    QLabel* m_languageLabel;
    QComboBox* m_language;
    QLabel* m_operatorLabel;
    QLineEdit* m_operator;
    QLabel* m_databaseLabel;
    QLabel* m_database;
    QLabel* m_sectionGeneral;
};

}  // namespace tt::ui
