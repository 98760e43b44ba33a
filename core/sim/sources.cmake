# Sources of core/sim, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    sim/normal_stream.cpp
    sim/stochastic_plant.cpp
    sim/run_to_run_analysis.cpp
    sim/run_to_run_monte_carlo.cpp
    sim/run_to_run_study.cpp
    sim/run_to_run_timing.cpp
    sim/dither_profile.cpp
    sim/cross_feed_drive.cpp
    sim/inductive_probe.cpp
    sim/boring_machine.cpp
    sim/probe_calibration_rig.cpp
    sim/boring_experiment.cpp
    sim/known_load_rig.cpp
)
include("${CMAKE_CURRENT_LIST_DIR}/lathe_sources.cmake")
