# CPack pre-build script: removes the .comment and .note sections from the staged executable and
# plugins (what Debian's dh_strip does beyond CPACK_STRIP_FILES' plain strip; lintian
# binary-has-unneeded-section). Runs on the staging folder, before the .deb and .tar.gz are made.
find_program(objcopy_program NAMES objcopy REQUIRED)
# The staging folder holds bin/ directly (.tar.gz) or under usr/ (.deb).
file(GLOB_RECURSE staged LIST_DIRECTORIES false "${CPACK_TEMPORARY_INSTALL_DIRECTORY}/*")
list(FILTER staged INCLUDE REGEX "/bin/trueturn$|/lib/trueturn/plugins/[^/]+\\.so$")
if(NOT staged)
    message(FATAL_ERROR "strip_comment.cmake: no executable or plugin under ${CPACK_TEMPORARY_INSTALL_DIRECTORY}")
endif()
foreach(binary IN LISTS staged)
    execute_process(COMMAND "${objcopy_program}" --remove-section=.comment --remove-section=.note "${binary}"
                    COMMAND_ERROR_IS_FATAL ANY)
endforeach()
