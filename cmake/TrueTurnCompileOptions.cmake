# Compile options shared by every TrueTurn target: warnings, optional -Werror, sanitizers.

add_library(trueturn_compile_options INTERFACE)
target_compile_options(trueturn_compile_options INTERFACE -Wall -Wextra -Wpedantic)
if(TRUETURN_WERROR)
    target_compile_options(trueturn_compile_options INTERFACE -Werror)
endif()
if(TRUETURN_SANITIZERS)
    target_compile_options(trueturn_compile_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(trueturn_compile_options INTERFACE -fsanitize=address,undefined)
endif()

# tt_target_defaults(<target>): the project's warnings and sanitizers for one target.
function(tt_target_defaults target)
    target_link_libraries(${target} PRIVATE trueturn_compile_options)
endfunction()

# trueturn_version: the generated header <trueturn/version.h> with tt::kVersion.
configure_file("${CMAKE_CURRENT_LIST_DIR}/version.h.in" "${PROJECT_BINARY_DIR}/generated/trueturn/version.h" @ONLY)
add_library(trueturn_version INTERFACE)
target_include_directories(trueturn_version INTERFACE "${PROJECT_BINARY_DIR}/generated")
