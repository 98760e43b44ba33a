#pragma once

#include <QString>
#include <cstdint>
#include <functional>
#include <memory>

#include "core/ports/shaft_machine.h"
#include "core/run/shaft_scenario.h"

namespace tt::devices {

/// A complete machine a plugin offers for shaft run-to-run runs: its own part cycle, CNC output and
/// gauge behind one core::ShaftMachine (the built-in simulator's lathe; a CNC plugin that reports its
/// own cycle end could offer its lathe the same way). The Run page lists the offers beside the lathe
/// assembled from the devices of the Devices page and never asks what is behind one.
struct ShaftMachineOffer {
    QString key;          ///< stable id, stored with the page's choices ("simulated-lathe")
    QString name;         ///< in the user's language when the offers were asked for
    QString description;  ///< one sentence for the page (what turns, measures and corrects the parts)
    /// Its time is simulated (ShaftMachine::jumpTo): the run paces it at a settable multiple of the wall clock.
    bool adjustableSpeed = false;
    /// The CNC that cuts the machine's parts, as the run request names it (RunRequest::cnc:
    /// "linuxcnc://HOST:PORT") and its correction mode; empty: none.
    QString cnc;
    QString cncMode;
    /// Makes the machine for one run of `scenario`, its random sources seeded by `seed`. Called in the loop's
    /// thread; the machine is used only there. Throws std::invalid_argument when the scenario does not suit
    /// the machine.
    std::function<std::unique_ptr<core::ShaftMachine>(const core::ShaftScenario& scenario, std::uint64_t seed)> make;
};

}  // namespace tt::devices
