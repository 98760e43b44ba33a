#pragma once

#include "ui/page.h"

namespace tt::ui {

class EmptyState;

/// A page whose engine part has not landed yet: it states plainly what the page will hold,
/// so the navigation is complete from the first build.
class PlannedPage : public Page {
    Q_OBJECT
public:
    PlannedPage(PageId id, AppContext& context, QWidget* parent = nullptr);
    QString title() const override;
    void retranslate() override;

private:
    EmptyState* m_state;
};

/// Translated navigation title of any page.
QString pageTitle(PageId id);

}  // namespace tt::ui
