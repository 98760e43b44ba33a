#pragma once

#include <QString>
#include <QWidget>

namespace tt::ui {

/// One process-design tool, shown as a tab of the Process page (feed scheduling, the corrective
/// pulse of the feed drives, hydraulic feed stabilisation). A tool builds its widgets in the
/// constructor and sets every user-visible text in retranslate().
class ProcessTool : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;
    /// Stable, untranslated key ("feed-schedule"), used for the tab's object name and screenshots.
    virtual QString key() const = 0;
    /// Translated tab title.
    virtual QString title() const = 0;
    /// Sets all user-visible texts (after construction and on a language change).
    virtual void retranslate() = 0;
};

}  // namespace tt::ui
