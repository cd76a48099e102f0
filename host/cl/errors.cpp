// OpenCL error codes by name, and the conversion of cl::Error into facet::Error.
#include <fmt/format.h>

#include "host/cl/runtime.hpp"
#include "host/error.hpp"

namespace facet {

const char* cl_error_name(cl_int code) {
    switch (code) {
#define FC_CASE(name) \
    case name:        \
        return #name;
        FC_CASE(CL_SUCCESS)
        FC_CASE(CL_DEVICE_NOT_FOUND)
        FC_CASE(CL_DEVICE_NOT_AVAILABLE)
        FC_CASE(CL_COMPILER_NOT_AVAILABLE)
        FC_CASE(CL_MEM_OBJECT_ALLOCATION_FAILURE)
        FC_CASE(CL_OUT_OF_RESOURCES)
        FC_CASE(CL_OUT_OF_HOST_MEMORY)
        FC_CASE(CL_PROFILING_INFO_NOT_AVAILABLE)
        FC_CASE(CL_MEM_COPY_OVERLAP)
        FC_CASE(CL_IMAGE_FORMAT_MISMATCH)
        FC_CASE(CL_IMAGE_FORMAT_NOT_SUPPORTED)
        FC_CASE(CL_BUILD_PROGRAM_FAILURE)
        FC_CASE(CL_MAP_FAILURE)
        FC_CASE(CL_MISALIGNED_SUB_BUFFER_OFFSET)
        FC_CASE(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
        FC_CASE(CL_COMPILE_PROGRAM_FAILURE)
        FC_CASE(CL_LINKER_NOT_AVAILABLE)
        FC_CASE(CL_LINK_PROGRAM_FAILURE)
        FC_CASE(CL_DEVICE_PARTITION_FAILED)
        FC_CASE(CL_KERNEL_ARG_INFO_NOT_AVAILABLE)
        FC_CASE(CL_INVALID_VALUE)
        FC_CASE(CL_INVALID_DEVICE_TYPE)
        FC_CASE(CL_INVALID_PLATFORM)
        FC_CASE(CL_INVALID_DEVICE)
        FC_CASE(CL_INVALID_CONTEXT)
        FC_CASE(CL_INVALID_QUEUE_PROPERTIES)
        FC_CASE(CL_INVALID_COMMAND_QUEUE)
        FC_CASE(CL_INVALID_HOST_PTR)
        FC_CASE(CL_INVALID_MEM_OBJECT)
        FC_CASE(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR)
        FC_CASE(CL_INVALID_IMAGE_SIZE)
        FC_CASE(CL_INVALID_SAMPLER)
        FC_CASE(CL_INVALID_BINARY)
        FC_CASE(CL_INVALID_BUILD_OPTIONS)
        FC_CASE(CL_INVALID_PROGRAM)
        FC_CASE(CL_INVALID_PROGRAM_EXECUTABLE)
        FC_CASE(CL_INVALID_KERNEL_NAME)
        FC_CASE(CL_INVALID_KERNEL_DEFINITION)
        FC_CASE(CL_INVALID_KERNEL)
        FC_CASE(CL_INVALID_ARG_INDEX)
        FC_CASE(CL_INVALID_ARG_VALUE)
        FC_CASE(CL_INVALID_ARG_SIZE)
        FC_CASE(CL_INVALID_KERNEL_ARGS)
        FC_CASE(CL_INVALID_WORK_DIMENSION)
        FC_CASE(CL_INVALID_WORK_GROUP_SIZE)
        FC_CASE(CL_INVALID_WORK_ITEM_SIZE)
        FC_CASE(CL_INVALID_GLOBAL_OFFSET)
        FC_CASE(CL_INVALID_EVENT_WAIT_LIST)
        FC_CASE(CL_INVALID_EVENT)
        FC_CASE(CL_INVALID_OPERATION)
        FC_CASE(CL_INVALID_GL_OBJECT)
        FC_CASE(CL_INVALID_BUFFER_SIZE)
        FC_CASE(CL_INVALID_MIP_LEVEL)
        FC_CASE(CL_INVALID_GLOBAL_WORK_SIZE)
        FC_CASE(CL_INVALID_PROPERTY)
        FC_CASE(CL_INVALID_IMAGE_DESCRIPTOR)
        FC_CASE(CL_INVALID_COMPILER_OPTIONS)
        FC_CASE(CL_INVALID_LINKER_OPTIONS)
        FC_CASE(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef FC_CASE
        case -1001:
            return "CL_PLATFORM_NOT_FOUND_KHR";
        default:
            return "CL_ERROR_UNKNOWN";
    }
}

void throw_cl_error(const char* what, const cl::Error& e) {
    std::string hint;
    if (e.err() == CL_OUT_OF_RESOURCES || e.err() == CL_MEM_OBJECT_ALLOCATION_FAILURE ||
        e.err() == CL_OUT_OF_HOST_MEMORY)
        hint = " (the device ran out of memory or resources: try a smaller image or scene)";
    throw Error(
        fmt::format("OpenCL error {} ({}) in {} while {}{}", cl_error_name(e.err()), e.err(), e.what(), what, hint));
}

}  // namespace facet
