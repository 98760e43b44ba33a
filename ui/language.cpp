#include "ui/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace tt::ui {

namespace {
const QString kSettingsKey = QStringLiteral("ui/language");
}

LanguageSwitcher::LanguageSwitcher(QObject* parent) : QObject(parent) {}

LanguageSwitcher::~LanguageSwitcher() {
    removeTranslators();
}

QStringList LanguageSwitcher::available() {
    return {QStringLiteral("en"), QStringLiteral("ru")};
}

QString LanguageSwitcher::nativeName(const QString& code) {
    if (code == QStringLiteral("ru")) return QStringLiteral("Русский");
    return QStringLiteral("English");
}

void LanguageSwitcher::removeTranslators() {
    if (m_appTranslator) QCoreApplication::removeTranslator(m_appTranslator.get());
    if (m_qtTranslator) QCoreApplication::removeTranslator(m_qtTranslator.get());
    m_appTranslator.reset();
    m_qtTranslator.reset();
}

bool LanguageSwitcher::apply(const QString& code) {
    if (!available().contains(code)) return false;
    auto app = std::make_unique<QTranslator>();
    if (!app->load(QStringLiteral(":/i18n/trueturn_%1.qm").arg(code))) return false;
    auto qt = std::make_unique<QTranslator>();
    const bool haveQt =
        qt->load(QStringLiteral("qtbase_%1").arg(code), QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    removeTranslators();
    m_appTranslator = std::move(app);
    QCoreApplication::installTranslator(m_appTranslator.get());
    if (haveQt) {
        m_qtTranslator = std::move(qt);
        QCoreApplication::installTranslator(m_qtTranslator.get());
    }
    m_current = code;
    QSettings().setValue(kSettingsKey, code);
    emit languageChanged(code);
    return true;
}

void LanguageSwitcher::applySaved() {
    apply(QSettings().value(kSettingsKey, QStringLiteral("en")).toString());
}

}  // namespace tt::ui
