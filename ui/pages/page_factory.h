#pragma once

#include "ui/page.h"

namespace tt::ui {

/// Creates the page widget for `id`. The one place that maps page ids to page classes.
Page* createPage(PageId id, AppContext& context, QWidget* parent);

}  // namespace tt::ui
