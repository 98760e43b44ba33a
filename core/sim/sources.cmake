# Sources of core/sim, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
)
