# Sources of core/ports, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
)
