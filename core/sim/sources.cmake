# Sources of core/sim, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    sim/normal_stream.cpp
    sim/stochastic_plant.cpp
    sim/run_to_run_analysis.cpp
    sim/run_to_run_monte_carlo.cpp
    sim/run_to_run_study.cpp
)
