# facet_embed_kernels(<target> NAME <name> DIRS <folder>... [EXCLUDE <folder>...] [REGISTER])
# Embeds the *.cl and *.h files under DIRS (folders relative to the repository root, less
# those under EXCLUDE) into <target> as the generated source generated/<name>.cpp
# (cmake/embed_kernels.cmake). The renderer's table (facet_core, no REGISTER) defines
# embedded_kernel_files(); a REGISTER table adds itself to the lookup of
# host/cl/kernel_source.cpp when its program starts, so the tests' kernels (kernels/test)
# and the bench's (kernels/bench) live in facet_tests and facet_bench only, not in facet.
function(facet_embed_kernels target)
    cmake_parse_arguments(PARSE_ARGV 1 arg "REGISTER" "NAME" "DIRS;EXCLUDE")
    set(files "")
    foreach(dir IN LISTS arg_DIRS)
        file(GLOB_RECURSE found CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/${dir}/*.cl" "${CMAKE_SOURCE_DIR}/${dir}/*.h")
        list(APPEND files ${found})
    endforeach()
    foreach(dir IN LISTS arg_EXCLUDE)
        list(FILTER files EXCLUDE REGEX "^${CMAKE_SOURCE_DIR}/${dir}/")
    endforeach()
    list(JOIN arg_DIRS "," dirs)
    list(JOIN arg_EXCLUDE "," excluded)
    set(register OFF)
    if(arg_REGISTER)
        set(register ON)
    endif()
    set(out "${CMAKE_BINARY_DIR}/generated/${arg_NAME}.cpp")
    add_custom_command(
        OUTPUT "${out}"
        COMMAND ${CMAKE_COMMAND} -DROOT=${CMAKE_SOURCE_DIR} -DOUT=${out} -DDIRS=${dirs} -DEXCLUDE=${excluded}
                -DREGISTER=${register} -P ${CMAKE_SOURCE_DIR}/cmake/embed_kernels.cmake
        DEPENDS ${files} ${CMAKE_SOURCE_DIR}/cmake/embed_kernels.cmake
        COMMENT "Embedding OpenCL kernel sources of ${dirs} (${arg_NAME})")
    target_sources(${target} PRIVATE "${out}")
endfunction()
