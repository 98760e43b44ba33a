# Sources of core/control, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
)
