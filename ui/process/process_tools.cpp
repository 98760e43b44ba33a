#include "ui/process/process_tools.h"

#include "ui/process/corner_tool.h"
#include "ui/process/feed_schedule_tool.h"
#include "ui/process/hydraulic_feed_tool.h"

namespace tt::ui {

std::vector<ProcessTool*> makeProcessTools(AppContext& context, QWidget* parent) {
    std::vector<ProcessTool*> tools;
    tools.push_back(new FeedScheduleTool(context, parent));
    tools.push_back(new CornerTool(context, parent));
    tools.push_back(new HydraulicFeedTool(context, parent));
    return tools;
}

}  // namespace tt::ui
