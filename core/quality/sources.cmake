# Sources of core/quality, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
)
