#pragma once

#include <QApplication>
#include <QTabWidget>

#include "ui/boring/boring_panel.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"

namespace tt::ui::test {

/// Shows `window` at the terminal's 1280 × 800 on the Run page's second tab, the in-process
/// compensation; its panel, or null when the page has no such tab.
inline BoringPanel* showBoringTab(MainWindow& window) {
    window.resize(1280, 800);
    window.show();
    window.showPage(PageId::Run);
    auto* run = dynamic_cast<RunPage*>(window.page(PageId::Run));
    if (!run || run->tabs()->count() < 2) return nullptr;
    run->tabs()->setCurrentIndex(1);
    QApplication::processEvents();
    return qobject_cast<BoringPanel*>(run->tabs()->widget(1));
}

}  // namespace tt::ui::test
