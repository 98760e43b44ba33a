#include "ui/process/process_tools.h"

#include "ui/process/feed_schedule_tool.h"

namespace tt::ui {

std::vector<ProcessTool*> makeProcessTools(AppContext& context, QWidget* parent) {
    std::vector<ProcessTool*> tools;
    // One line per tool.
    tools.push_back(new FeedScheduleTool(context, parent));
    return tools;
}

}  // namespace tt::ui
