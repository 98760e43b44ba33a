#pragma once

#include "core/sim/boring/boring_machine.h"

namespace tt::core::test {

/// The heavy-boring scenario with the values of resources/presets/heavy-boring.json (the core
/// tests do not read JSON; tests/app/boring checks the preset itself through the binary).
inline BoringScenario heavyBoring() {
    BoringScenario s;
    s.name = "heavy-boring";
    s.tool.id = "T12";
    s.tool.name = "Boring bar D80 L800";
    s.tool.section = HolderSection::round(80.0);
    s.tool.overhangMm = 800.0;  // L/d = 10
    s.tool.material = "Steel";
    s.tool.youngsModulusMpa = 210'000.0;
    s.tool.currentToForceGainNPerA = 150.0;
    s.trueStiffnessFactor = 0.97;
    s.cut = BoringCutConfig{};         // 500 mm bore, f 0.3 mm/rev, 190 rpm, K_r 1000 N/mm², stock 0.8 .. 1.2 mm
    s.drive = CrossFeedDriveConfig{};  // F_c 900 N (3 × the mean cutting force), k_p 150 N/A
    s.dither = DitherConfig{0.01, 0.5, 0.6};
    s.probe = InductiveProbeConfig{};  // 12 bits, r(u) = 0.80 u + 0.15 u³
    s.limits = CompensatorLimits{0.5, 0.05};
    s.plcCycleS = 0.02;
    s.simStepS = 1.0e-4;
    s.seed = 1;
    return s;
}

}  // namespace tt::core::test
