#pragma once

#include "devices/api/shaft_machine_offer.h"

namespace tt::devices {

/// The built-in simulator's lathe for shaft runs: the simulated shop of the run's scenario (physical
/// lathe or statistical plant with its CNC, gauge and part cycle, core::SimulatedLathe) running at a
/// settable multiple of the wall clock.
ShaftMachineOffer simulatedLatheOffer();

}  // namespace tt::devices
