#include "ui/pages/page_factory.h"

#include "ui/pages/calibration_page.h"
#include "ui/pages/controller_page.h"
#include "ui/pages/devices_page.h"
#include "ui/pages/measurements_page.h"
#include "ui/pages/plant_page.h"
#include "ui/pages/planned_page.h"
#include "ui/pages/process_page.h"
#include "ui/pages/reports_page.h"
#include "ui/pages/run_page.h"
#include "ui/pages/settings_page.h"
#include "ui/pages/tools_page.h"

namespace tt::ui {

Page* createPage(PageId id, AppContext& context, QWidget* parent) {
    switch (id) {
        case PageId::Run:
            return new RunPage(context, parent);
        case PageId::Measurements:
            return new MeasurementsPage(context, parent);
        case PageId::Settings:
            return new SettingsPage(context, parent);
        case PageId::Tools:
            return new ToolsPage(context, parent);
        case PageId::Calibration:
            return new CalibrationPage(context, parent);
        case PageId::Process:
            return new ProcessPage(context, parent);
        case PageId::Devices:
            return new DevicesPage(context, parent);
        case PageId::Reports:
            return new ReportsPage(context, parent);
        case PageId::Plant:
            return new PlantPage(context, parent);
        case PageId::Controller:
            return new ControllerPage(context, parent);
        default:
            return new PlannedPage(id, context, parent);
    }
}

}  // namespace tt::ui
