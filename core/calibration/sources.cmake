# Sources of core/calibration, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    calibration/probe_linearisation.cpp
    calibration/linearisation_table.cpp
    calibration/calibration_csv.cpp
    calibration/linearisation_image.cpp
    calibration/kp_calibration.cpp
)
