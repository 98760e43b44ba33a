#pragma once

#include <QObject>
#include <optional>

#include "core/control/run_to_run_setup.h"

namespace tt::ui {

/// The controller tuning the commissioning engineer applied on the Controller page, shared with the Run
/// page through AppContext::tuning (issue 13 item 6): a running shaft loop takes it over at its next part
/// (bumpless, LoopEngine::replaceController), and the next Start designs its controller with it.
class ControllerTuning : public QObject {
    Q_OBJECT
public:
    explicit ControllerTuning(QObject* parent = nullptr) : QObject(parent) {}

    /// The setup last applied; none before the first Apply (a run then uses its preset's tuning).
    const std::optional<core::RunToRunSetup>& current() const { return m_current; }
    /// Keeps `setup` as the applied tuning and tells whoever runs a loop (the signal `applied`).
    void apply(const core::RunToRunSetup& setup) {
        m_current = setup;
        emit applied(setup);
    }
    /// A shaft loop is running (or paused) and takes an applied tuning at its next part (the Run page says so).
    bool loopTakesTuning() const { return m_loopTakesTuning; }
    void setLoopTakesTuning(bool takes) { m_loopTakesTuning = takes; }

signals:
    /// A new tuning was applied (on the GUI thread).
    void applied(const tt::core::RunToRunSetup& setup);

private:
    std::optional<core::RunToRunSetup> m_current;
    bool m_loopTakesTuning = false;
};

}  // namespace tt::ui
