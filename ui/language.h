#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>

class QTranslator;

namespace tt::ui {

/// Switches the user-interface language at run time (English, Russian) with Qt Linguist
/// translations built into the binary (:/i18n/trueturn_<code>.qm) plus Qt's own strings.
/// The choice is kept in QSettings ("ui/language").
class LanguageSwitcher : public QObject {
    Q_OBJECT
public:
    explicit LanguageSwitcher(QObject* parent = nullptr);
    ~LanguageSwitcher() override;

    /// Language codes offered to the user, in display order ("en", "ru").
    static QStringList available();
    /// The language's own name ("English", "Русский").
    static QString nativeName(const QString& code);

    QString current() const { return m_current; }
    /// Installs the translators for `code` (retranslating every widget). Returns false and
    /// keeps the current language when `code` is unknown or its translation cannot be loaded.
    bool apply(const QString& code);
    /// Applies the language stored in the settings (English when none).
    void applySaved();

signals:
    void languageChanged(const QString& code);

private:
    void removeTranslators();

    QString m_current = QStringLiteral("en");
    std::unique_ptr<QTranslator> m_appTranslator;
    std::unique_ptr<QTranslator> m_qtTranslator;
};

}  // namespace tt::ui
