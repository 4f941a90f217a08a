# Shared by the gazelle interface packages: run the generators a Python user needs, and only those.
#
# rclpy publishes through the C type support (rosidl_typesupport_c, which dispatches to Fast DDS's C
# type support or to the C introspection one) and the Python bindings. The C++ generators and type
# supports are for C++ nodes, which a pip install never compiles; yet they register themselves as
# soon as any message package is found (std_msgs exports rosidl_default_runtime, which finds
# rosidl_typesupport_cpp, which finds the C++ generators). gazelle_generate_interfaces() drops them
# from the extension point just before rosidl_generate_interfaces(): gazebo_msgs builds in 78 s
# instead of 188 s on 2 cores.
#
# Include this after find_package(ament_cmake), in place of find_package(rosidl_default_generators).
find_package(rosidl_cmake REQUIRED)
find_package(rosidl_generator_type_description REQUIRED)
find_package(rosidl_generator_c REQUIRED)
find_package(rosidl_typesupport_introspection_c REQUIRED)
find_package(rosidl_typesupport_fastrtps_c REQUIRED)
find_package(rosidl_typesupport_c REQUIRED)
find_package(rosidl_generator_py REQUIRED)

set(GAZELLE_CXX_GENERATORS
  rosidl_generator_cpp rosidl_typesupport_cpp rosidl_typesupport_fastrtps_cpp rosidl_typesupport_introspection_cpp)

macro(gazelle_generate_interfaces)
  set(_gazelle_kept)
  foreach(_gazelle_ext IN LISTS AMENT_EXTENSIONS_rosidl_generate_idl_interfaces)
    string(REPLACE ":" ";" _gazelle_parts "${_gazelle_ext}")
    list(GET _gazelle_parts 0 _gazelle_pkg)
    if(NOT _gazelle_pkg IN_LIST GAZELLE_CXX_GENERATORS)
      list(APPEND _gazelle_kept "${_gazelle_ext}")
    endif()
  endforeach()
  set(AMENT_EXTENSIONS_rosidl_generate_idl_interfaces ${_gazelle_kept})
  rosidl_generate_interfaces(${ARGN})
  # Most of a build is the compilers parsing the same headers again for every message: Fast-CDR's
  # templates in each Fast DDS type support file, Python's and NumPy's headers in each binding.
  # Parsed once per package instead (measured on moveit_msgs' planning_scene: 0.51 s -> 0.20 s a file).
  set(_gazelle_args ${ARGN})
  list(GET _gazelle_args 0 _gazelle_target)
  if(TARGET ${_gazelle_target}__rosidl_typesupport_fastrtps_c)
    target_precompile_headers(${_gazelle_target}__rosidl_typesupport_fastrtps_c PRIVATE
      <cassert> <cstddef> <limits> <string>
      <rosidl_typesupport_fastrtps_c/identifier.h>
      <rosidl_typesupport_fastrtps_c/serialization_helpers.hpp>
      <rosidl_typesupport_fastrtps_c/wstring_conversion.hpp>
      <rosidl_typesupport_fastrtps_cpp/message_type_support.h>
      <fastcdr/Cdr.h>)
  endif()
  if(TARGET ${_gazelle_target}__rosidl_generator_py)
    # the bindings define this before they include NumPy; the precompiled header comes first
    target_compile_definitions(${_gazelle_target}__rosidl_generator_py PRIVATE
      NPY_NO_DEPRECATED_API=NPY_1_7_API_VERSION)
    target_precompile_headers(${_gazelle_target}__rosidl_generator_py PRIVATE
      <Python.h> <stdbool.h> <numpy/ndarrayobject.h>)
  endif()
endmacro()
