# Sources of core/model, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    model/shaping_filter.cpp
    model/disturbance_model.cpp
    model/scaled_polynomial.cpp
    model/polynomial_regression.cpp
    model/systematic_error_model.cpp
    model/tool_stiffness.cpp
    model/tool_table.cpp
    model/tool_table_csv.cpp
)
