#include "ui/process/process_tools.h"

#include "ui/process/hydraulic_feed_tool.h"

namespace tt::ui {

std::vector<ProcessTool*> makeProcessTools(AppContext& context, QWidget* parent) {
    (void)context;
    std::vector<ProcessTool*> tools;
    // One line per tool: tools.push_back(new FeedScheduleTool(context, parent));
    tools.push_back(new HydraulicFeedTool(context, parent));
    (void)parent;
    return tools;
}

}  // namespace tt::ui
