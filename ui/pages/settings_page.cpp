#include "ui/pages/settings_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QVBoxLayout>

#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/pages/planned_page.h"

namespace tt::ui {

namespace {
const QString kOperatorKey = QStringLiteral("operator/name");
}

SettingsPage::SettingsPage(AppContext& context, QWidget* parent)
    : Page(PageId::Settings, context, parent),
      m_languageLabel(new QLabel(this)),
      m_language(new QComboBox(this)),
      m_operatorLabel(new QLabel(this)),
      m_operator(new QLineEdit(this)),
      m_databaseLabel(new QLabel(this)),
      m_database(new QLabel(this)),
      m_sectionGeneral(new QLabel(this)) {
    m_sectionGeneral->setObjectName(QStringLiteral("SectionTitle"));
    m_language->setObjectName(QStringLiteral("languageCombo"));
    m_operator->setObjectName(QStringLiteral("operatorEdit"));
    m_operator->setMaxLength(64);
    m_database->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_database->setWordWrap(true);

    auto* form = new QFormLayout;
    form->setVerticalSpacing(16);
    form->addRow(m_languageLabel, m_language);
    form->addRow(m_operatorLabel, m_operator);
    form->addRow(m_databaseLabel, m_database);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(32, 24, 32, 24);
    layout->addWidget(m_sectionGeneral);
    layout->addLayout(form);
    layout->addStretch(1);

    fillLanguages();
    const QString savedOperator = QSettings().value(kOperatorKey).toString();
    m_operator->setText(savedOperator);
    if (context.state) context.state->setOperatorName(savedOperator);
    m_database->setText(context.databasePath);

    connect(m_language, &QComboBox::activated, this, &SettingsPage::onLanguageChosen);
    connect(m_operator, &QLineEdit::editingFinished, this, &SettingsPage::onOperatorEdited);
    retranslate();
}

QString SettingsPage::title() const {
    return pageTitle(PageId::Settings);
}

void SettingsPage::fillLanguages() {
    for (const QString& code : LanguageSwitcher::available())
        m_language->addItem(LanguageSwitcher::nativeName(code), code);
    if (context().language) m_language->setCurrentIndex(m_language->findData(context().language->current()));
}

void SettingsPage::onLanguageChosen(int index) {
    if (context().language) context().language->apply(m_language->itemData(index).toString());
}

void SettingsPage::onOperatorEdited() {
    const QString name = m_operator->text().trimmed();
    QSettings().setValue(kOperatorKey, name);
    if (context().state) context().state->setOperatorName(name);
}

void SettingsPage::retranslate() {
    m_sectionGeneral->setText(tr("Terminal"));
    m_languageLabel->setText(tr("Language"));
    m_operatorLabel->setText(tr("Operator"));
    m_operator->setPlaceholderText(tr("Name recorded with every change you apply"));
    m_databaseLabel->setText(tr("Run history"));
    if (context().language) m_language->setCurrentIndex(m_language->findData(context().language->current()));
}

}  // namespace tt::ui
