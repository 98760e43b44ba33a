# Sources of core/calibration, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
)
