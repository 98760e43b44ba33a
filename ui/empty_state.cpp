#include "ui/empty_state.h"

#include <QLabel>
#include <QVBoxLayout>

namespace tt::ui {

EmptyState::EmptyState(QWidget* parent) : QWidget(parent), m_title(new QLabel(this)), m_text(new QLabel(this)) {
    m_title->setObjectName(QStringLiteral("EmptyStateTitle"));
    m_text->setObjectName(QStringLiteral("EmptyStateText"));
    m_title->setAlignment(Qt::AlignCenter);
    m_text->setAlignment(Qt::AlignCenter);
    m_title->setWordWrap(true);
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::RichText);
    auto* layout = new QVBoxLayout(this);
    layout->addStretch(1);
    layout->addWidget(m_title);
    layout->addSpacing(12);
    layout->addWidget(m_text);
    layout->addStretch(2);
    layout->setContentsMargins(48, 24, 48, 24);
}

void EmptyState::setTexts(const QString& title, const QString& text) {
    m_title->setText(title);
    m_text->setText(text);
}

}  // namespace tt::ui
