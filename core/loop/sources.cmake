# Sources of core/loop, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    loop/measurement_session.cpp
)
