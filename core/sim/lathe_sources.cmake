# Sources of the lathe simulator for shafts between centres (paper 000), compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    sim/lathe_setup.cpp
    sim/lathe_cutting_force.cpp
    sim/lathe_shaft_beam.cpp
    sim/lathe_random.cpp
    sim/lathe_disturbance.cpp
    sim/lathe_part_process.cpp
    sim/lathe_micrometer.cpp
    sim/lathe_simulator.cpp
    sim/lathe_statistical_process.cpp
    sim/lathe_station.cpp
    sim/lathe_shop.cpp
    sim/lathe_run.cpp
    sim/lathe_study.cpp
)
