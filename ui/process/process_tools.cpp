#include "ui/process/process_tools.h"

#include "ui/process/corner_tool.h"

namespace tt::ui {

std::vector<ProcessTool*> makeProcessTools(AppContext& context, QWidget* parent) {
    (void)context;
    std::vector<ProcessTool*> tools;
    // One line per tool: tools.push_back(new FeedScheduleTool(context, parent));
    tools.push_back(new CornerTool(context, parent));
    (void)parent;
    return tools;
}

}  // namespace tt::ui
