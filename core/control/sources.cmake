# Sources of core/control, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    control/profile_interpolation.cpp
    control/correction_path_builder.cpp
)
