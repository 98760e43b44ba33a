#include "ui/pages/planned_page.h"

#include <QVBoxLayout>

#include "ui/empty_state.h"

namespace tt::ui {

QString pageTitle(PageId id) {
    switch (id) {
        case PageId::Run:
            return PlannedPage::tr("Run");
        case PageId::Measurements:
            return PlannedPage::tr("Measurements");
        case PageId::Tools:
            return PlannedPage::tr("Tools");
        case PageId::Calibration:
            return PlannedPage::tr("Calibration");
        case PageId::Process:
            return PlannedPage::tr("Process");
        case PageId::Controller:
            return PlannedPage::tr("Controller");
        case PageId::Reports:
            return PlannedPage::tr("Reports");
        case PageId::Plant:
            return PlannedPage::tr("Plant");
        case PageId::Devices:
            return PlannedPage::tr("Devices");
        case PageId::Settings:
            return PlannedPage::tr("Settings");
    }
    return {};
}

PlannedPage::PlannedPage(PageId id, AppContext& context, QWidget* parent)
    : Page(id, context, parent), m_state(new EmptyState(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_state);
    retranslate();
}

QString PlannedPage::title() const {
    return pageTitle(id());
}

void PlannedPage::retranslate() {
    switch (id()) {
        case PageId::Run:
            m_state->setTexts(tr("Closed-loop run"),
                              tr("Start, pause and stop the run-to-run loop; the profile error of the last part "
                                 "against the tolerance band; the correction path; alarms."));
            break;
        case PageId::Measurements:
            m_state->setTexts(tr("No parts measured yet"),
                              tr("Measured diameters of every part at the control points, accepted or rejected "
                                 "with the reason, and manual entry for a hand micrometer."));
            break;
        case PageId::Tools:
            m_state->setTexts(tr("Tool stiffness table"),
                              tr("Boring bars and holders: section, overhang, material, computed and measured "
                                 "stiffness (N/mm), and the cross-feed current-to-force gain k<sub>p</sub>."));
            break;
        case PageId::Calibration:
            m_state->setTexts(tr("Calibration wizards"),
                              tr("Probe-mandrel linearisation (ADC code to deflection table) and the "
                                 "current-to-force gain k<sub>p</sub> from known loads."));
            break;
        case PageId::Controller:
            m_state->setTexts(tr("Controller tuning"),
                              tr("Transport delay z, weights R1 and R2, correction limits, the disturbance model "
                                 "and the resulting LQG gains."));
            break;
        case PageId::Devices:
            m_state->setTexts(tr("Devices"),
                              tr("Gauge micrometer, probe mandrel, drive-current readout and the correction output "
                                 "to the CNC; the built-in simulator is always available."));
            break;
        case PageId::Reports:  // ReportsPage
        case PageId::Plant:    // PlantPage
        case PageId::Process:  // ProcessPage
        case PageId::Settings:
            break;
    }
}

}  // namespace tt::ui
