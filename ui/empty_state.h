#pragma once

#include <QWidget>

class QLabel;

namespace tt::ui {

/// A large, centred explanation of what a page or panel shows once it has data
/// ("No runs recorded yet: reports show ..."). Never an empty page.
class EmptyState : public QWidget {
    Q_OBJECT
public:
    explicit EmptyState(QWidget* parent = nullptr);
    void setTexts(const QString& title, const QString& text);

private:
    QLabel* m_title;
    QLabel* m_text;
};

}  // namespace tt::ui
