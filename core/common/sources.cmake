# Sources of core/common, compiled into trueturn_core.
target_sources(trueturn_core PRIVATE
    common/crc16.cpp
    common/text_format.cpp
    common/crc32c.cpp
)
