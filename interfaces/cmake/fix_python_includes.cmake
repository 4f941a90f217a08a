# Shared helper for the gazelle interface packages.
#
# The rosidl/ament wheels from PyPI export `<pkg>::<pkg>__rosidl_generator_py`
# targets whose INTERFACE_INCLUDE_DIRECTORIES point at the Python headers of the
# machine that built the wheels (/opt/python/cp311-cp311/include/python3.11).
# That directory does not exist here, so CMake refuses to generate. Point every
# such imported target (direct and transitive dependencies alike) at the headers
# of the interpreter we build for.
#
# Include this file after the package's find_package() calls. The fix is applied
# right away and once more at the end of the directory (cmake_language DEFER),
# so targets imported later by rosidl_generate_interfaces() (e.g. action_msgs,
# service_msgs) are covered too.

if(CMAKE_VERSION VERSION_LESS 3.19)
  message(FATAL_ERROR "CMake >= 3.19 is required (cmake_language(DEFER))")
endif()

find_package(Python3 REQUIRED COMPONENTS Interpreter Development)

function(gazelle_fix_python_includes)
  get_property(_targets DIRECTORY PROPERTY IMPORTED_TARGETS)
  foreach(_tgt IN LISTS _targets)
    if(_tgt MATCHES "__rosidl_generator_py$")
      set_target_properties(${_tgt} PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${Python3_INCLUDE_DIRS}")
    endif()
  endforeach()
endfunction()

gazelle_fix_python_includes()
cmake_language(DEFER CALL gazelle_fix_python_includes)
