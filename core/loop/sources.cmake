# Sources of core/loop, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    loop/measurement_session.cpp
    loop/loop_clock.cpp
    loop/loop_config.cpp
    loop/correction_limiter.cpp
    loop/manual_gauge.cpp
    loop/loop_engine.cpp
    loop/loop_runner.cpp
    loop/gauge_relay.cpp
    loop/correction_relay.cpp
    loop/operator_cycle.cpp
)
