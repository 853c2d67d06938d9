# Find MUMPS, double precision, parallel (Debian's libmumps-dev has no CMake config).
# Defines MUMPS::MUMPS (dmumps with its common library; link MPI beside it).
find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
find_library(MUMPS_DMUMPS_LIBRARY dmumps)
find_library(MUMPS_COMMON_LIBRARY mumps_common)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_DMUMPS_LIBRARY MUMPS_COMMON_LIBRARY
                                                      MUMPS_INCLUDE_DIR)
if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS UNKNOWN IMPORTED)
  set_target_properties(MUMPS::MUMPS PROPERTIES
    IMPORTED_LOCATION "${MUMPS_DMUMPS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${MUMPS_COMMON_LIBRARY}")
endif()
mark_as_advanced(MUMPS_INCLUDE_DIR MUMPS_DMUMPS_LIBRARY MUMPS_COMMON_LIBRARY)
