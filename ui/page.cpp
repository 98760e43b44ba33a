#include "ui/page.h"

#include <QEvent>

namespace tt::ui {

QString pageKey(PageId id) {
    switch (id) {
        case PageId::Run:
            return QStringLiteral("run");
        case PageId::Measurements:
            return QStringLiteral("measurements");
        case PageId::Tools:
            return QStringLiteral("tools");
        case PageId::Calibration:
            return QStringLiteral("calibration");
        case PageId::Process:
            return QStringLiteral("process");
        case PageId::Controller:
            return QStringLiteral("controller");
        case PageId::Reports:
            return QStringLiteral("reports");
        case PageId::Plant:
            return QStringLiteral("plant");
        case PageId::Devices:
            return QStringLiteral("devices");
        case PageId::Settings:
            return QStringLiteral("settings");
    }
    return {};
}

Page::Page(PageId id, AppContext& context, QWidget* parent) : QWidget(parent), m_id(id), m_context(context) {}

QIcon Page::icon() const {
    return QIcon(QStringLiteral(":/icons/%1.svg").arg(pageKey(m_id)));
}

void Page::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

}  // namespace tt::ui
