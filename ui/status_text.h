#pragma once

#include <QLabel>
#include <QString>
#include <functional>
#include <utility>

namespace tt::ui {

/// A status line whose text is made by a function, so that a change of language can make it again: "Written:
/// report.pdf" stays in the language the user chose, not the one that was on when the work ended.
class StatusText {
public:
    explicit StatusText(QLabel* label) : m_label(label) {}

    /// Shows what `make` gives now and keeps `make` for retranslate().
    void set(std::function<QString()> make) {
        m_make = std::move(make);
        retranslate();
    }
    /// Shows `fixed` (a message from the engine or the system, not translated here).
    void setFixed(const QString& fixed) {
        set([fixed] { return fixed; });
    }
    /// Forgets the text (the label keeps what it shows until the next set()).
    void clear() { m_make = nullptr; }
    /// Whether a text was set since the last clear().
    bool isSet() const { return static_cast<bool>(m_make); }
    /// Makes the text again in the current language.
    void retranslate() {
        if (m_make) m_label->setText(m_make());
    }

private:
    QLabel* m_label;
    std::function<QString()> m_make;
};

}  // namespace tt::ui
