#pragma once

#include <vector>

#include "ui/app_context.h"
#include "ui/process/process_tool.h"

namespace tt::ui {

/// Every process-design tool, in tab order (ui/process/process_tools.cpp: one line per tool).
std::vector<ProcessTool*> makeProcessTools(AppContext& context, QWidget* parent);

}  // namespace tt::ui
