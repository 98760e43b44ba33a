# Sources of core/control, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    control/dare.cpp
    control/stein.cpp
    control/lq_regulator.cpp
    control/kalman_filter.cpp
    control/run_to_run_plant.cpp
    control/lqg_design.cpp
    control/correction_limits.cpp
    control/run_to_run_checks.cpp
    control/lqg_controller.cpp
    control/ewma_controller.cpp
    control/run_to_run_setup.cpp
    control/profile_interpolation.cpp
    control/correction_path_builder.cpp
    control/dither_force_estimator.cpp
    control/deflection_compensator.cpp
    control/in_process_compensation.cpp
)
