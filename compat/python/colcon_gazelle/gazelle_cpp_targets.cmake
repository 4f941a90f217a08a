# gazelle: compiled targets that cannot be built in a gazelle venv, and the rest of their package.
#
# colcon includes this file in every CMake package it builds (gazelle's colcon extension, colcon_gazelle,
# passes -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=<this file>; CMake includes it in the package's first project()).
#
# A gazelle venv has no C++ ROS 2 or Gazebo libraries (rclcpp, gz-sim, Gazebo Classic, hardware_interface,
# pluginlib, ...): a package that compiles a node or a plugin against them could not configure, and colcon
# stopped before installing the package's launch files, worlds, models and configs. Here:
#
# * a REQUIRED find_package() that finds nothing (and a gazelle stand-in config of a package that exists
#   only at run time, such as gazebo_ros) makes the package "unavailable": its <pkg>_FOUND is set, its
#   <pkg>_TARGETS/<pkg>_LIBRARIES name the interface target gazelle_unavailable::<pkg>, and the CMake
#   functions it would define for its users (rclcpp_components_register_node(s),
#   pluginlib_export_plugin_description_file) do nothing;
# * at the end of the package's top-level CMakeLists, each compiled target that
#   gazelle_cpp_target_unbuildable() says cannot build is rebuilt from a placeholder source: one NOTICE
#   line (stderr, which colcon shows) names the target and what it needs. An executable placeholder
#   prints that line and exits 1 when run; a library placeholder is empty. install(TARGETS) then installs
#   the placeholders, and every other install() of the package is as written.
#
# gazelle_cpp_target_unbuildable() is the one decision; a tier that provides real C++ libraries replaces
# it (or makes their find_package() succeed, which takes them out of the unavailable set).

include_guard(GLOBAL)

set_property(GLOBAL PROPERTY GAZELLE_UNAVAILABLE_PACKAGES "")
set_property(GLOBAL PROPERTY GAZELLE_PROJECT_TARGETS "")

# Marks <pkg> unavailable and sets, in the caller's scope, what a found package sets.
function(gazelle_unavailable_package pkg)
  get_property(_known GLOBAL PROPERTY GAZELLE_UNAVAILABLE_PACKAGES)
  set(_target "gazelle_unavailable::${pkg}")
  if(NOT TARGET "${_target}")
    add_library("${_target}" INTERFACE IMPORTED GLOBAL)
    set_property(TARGET "${_target}" PROPERTY GAZELLE_UNAVAILABLE "${pkg}")
  endif()
  if(NOT pkg IN_LIST _known)
    set_property(GLOBAL APPEND PROPERTY GAZELLE_UNAVAILABLE_PACKAGES "${pkg}")
    message(STATUS "gazelle: ${pkg} is not available here (no C++ ROS 2 or Gazebo libraries); "
      "compiled targets that need it are not built")
  endif()
  string(TOUPPER "${pkg}" _upper)
  string(REPLACE "-" "_" _upper "${_upper}")
  set(_version "0.0.0")
  if(pkg MATCHES "([0-9]+)$")
    set(_version "${CMAKE_MATCH_1}.0.0")
  endif()
  string(REPLACE "." ";" _parts "${_version}")
  list(GET _parts 0 _major)
  foreach(_prefix "${pkg}" "${_upper}")
    set(${_prefix}_FOUND TRUE PARENT_SCOPE)
    set(${_prefix}_VERSION "${_version}" PARENT_SCOPE)
    set(${_prefix}_VERSION_MAJOR "${_major}" PARENT_SCOPE)
    set(${_prefix}_INCLUDE_DIRS "" PARENT_SCOPE)
    set(${_prefix}_LIBRARY_DIRS "" PARENT_SCOPE)
    set(${_prefix}_DEFINITIONS "" PARENT_SCOPE)
    set(${_prefix}_LIBRARIES "${_target}" PARENT_SCOPE)
    set(${_prefix}_TARGETS "${_target}" PARENT_SCOPE)
  endforeach()
  _gazelle_unavailable_functions("${pkg}")
endfunction()

# The CMake functions an unavailable package would define for its users.
function(_gazelle_unavailable_functions pkg)
  if(pkg STREQUAL "rclcpp_components" AND NOT COMMAND rclcpp_components_register_nodes)
    function(rclcpp_components_register_nodes target)
    endfunction()
    function(rclcpp_components_register_node target)
      cmake_parse_arguments(_arg "" "PLUGIN;EXECUTABLE;EXECUTOR;RESOURCE_INDEX" "" ${ARGN})
      if(_arg_EXECUTABLE)
        add_executable(${_arg_EXECUTABLE})
        set_property(TARGET ${_arg_EXECUTABLE} PROPERTY LINK_LIBRARIES
          gazelle_unavailable::rclcpp_components ${target})
        install(TARGETS ${_arg_EXECUTABLE} DESTINATION lib/${PROJECT_NAME})
      endif()
    endfunction()
  elseif(pkg STREQUAL "pluginlib" AND NOT COMMAND pluginlib_export_plugin_description_file)
    function(pluginlib_export_plugin_description_file base file)
    endfunction()
  endif()
endfunction()

# find_package() as CMake's, but a REQUIRED package that is not found is unavailable, not an error.
macro(find_package)
  _gazelle_find_arguments(_gazelle_fp_args_${ARGV0} _gazelle_fp_required_${ARGV0} ${ARGV})
  _find_package(${_gazelle_fp_args_${ARGV0}})
  if(_gazelle_fp_required_${ARGV0} AND NOT ${ARGV0}_FOUND)
    gazelle_unavailable_package("${ARGV0}")
  endif()
endmacro()

function(_gazelle_find_arguments out_args out_required)
  set(_args ${ARGN})
  set(_required FALSE)
  if("REQUIRED" IN_LIST _args)
    set(_required TRUE)
    list(REMOVE_ITEM _args REQUIRED)
    if(NOT "QUIET" IN_LIST _args)
      list(APPEND _args QUIET)
    endif()
  endif()
  set(${out_args} "${_args}" PARENT_SCOPE)
  set(${out_required} ${_required} PARENT_SCOPE)
endfunction()

function(add_executable name)
  _add_executable(${ARGV})
  _gazelle_track_target(${ARGV})
endfunction()

function(add_library name)
  _add_library(${ARGV})
  _gazelle_track_target(${ARGV})
endfunction()

function(_gazelle_track_target name)
  if(NOT "IMPORTED" IN_LIST ARGN AND NOT "ALIAS" IN_LIST ARGN)
    set_property(GLOBAL APPEND PROPERTY GAZELLE_PROJECT_TARGETS "${name}")
  endif()
endfunction()

# What a link item needs that is unavailable (package names, or "<target> (not built)"), into out.
function(_gazelle_link_item_needs item visited out)
  set(_needs "")
  if(item MATCHES "^\\$<(LINK_ONLY|BUILD_INTERFACE):(.*)>$")
    set(item "${CMAKE_MATCH_2}")
  endif()
  get_property(_unavailable GLOBAL PROPERTY GAZELLE_UNAVAILABLE_PACKAGES)
  if(item MATCHES "^\\$<" OR item STREQUAL "" OR "${item}" IN_LIST visited)
    # a generator expression gazelle does not evaluate, or seen already
  elseif(TARGET "${item}")
    get_target_property(_pkg "${item}" GAZELLE_UNAVAILABLE)
    get_target_property(_imported "${item}" IMPORTED)
    if(_pkg)
      list(APPEND _needs "${_pkg}")
    elseif(NOT _imported)
      gazelle_cpp_target_unbuildable("${item}" _reason)
      if(_reason)
        list(APPEND _needs "${item} (not built)")
      endif()
    else()
      get_target_property(_deps "${item}" INTERFACE_LINK_LIBRARIES)
      list(APPEND visited "${item}")
      foreach(_dep IN LISTS _deps)
        _gazelle_link_item_needs("${_dep}" "${visited}" _more)
        list(APPEND _needs ${_more})
      endforeach()
    endif()
  elseif(item MATCHES "^([^:$<>]+)::")
    list(APPEND _needs "${CMAKE_MATCH_1}")  # a package's namespaced target that no package defined
  elseif("${item}" IN_LIST _unavailable)
    list(APPEND _needs "${item}")
  endif()
  list(REMOVE_DUPLICATES _needs)
  set(${out} "${_needs}" PARENT_SCOPE)
endfunction()

# THE decision: sets out to what <target> needs that is not available here ("" when it can be built).
# A target with nothing to compile (an INTERFACE library) or linking only what exists is built as written.
function(gazelle_cpp_target_unbuildable target out)
  get_property(_memo GLOBAL PROPERTY "GAZELLE_UNBUILDABLE_${target}" SET)
  if(_memo)
    get_property(_reason GLOBAL PROPERTY "GAZELLE_UNBUILDABLE_${target}")
    set(${out} "${_reason}" PARENT_SCOPE)
    return()
  endif()
  set_property(GLOBAL PROPERTY "GAZELLE_UNBUILDABLE_${target}" "")  # a cycle decides "buildable"
  get_target_property(_type "${target}" TYPE)
  set(_needs "")
  if(NOT _type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(_private "${target}" LINK_LIBRARIES)
    get_target_property(_public "${target}" INTERFACE_LINK_LIBRARIES)
    foreach(_item IN LISTS _private _public)
      if(_item)
        _gazelle_link_item_needs("${_item}" "${target}" _more)
        list(APPEND _needs ${_more})
      endif()
    endforeach()
    list(REMOVE_DUPLICATES _needs)
  endif()
  list(JOIN _needs ", " _reason)
  set_property(GLOBAL PROPERTY "GAZELLE_UNBUILDABLE_${target}" "${_reason}")
  set(${out} "${_reason}" PARENT_SCOPE)
endfunction()

# Rebuilds <target> from a placeholder source that says why the real one is not built.
function(_gazelle_placeholder target reason)
  get_target_property(_type "${target}" TYPE)
  get_property(_languages GLOBAL PROPERTY ENABLED_LANGUAGES)
  set(_ext "c")
  set(_lang C)
  if(NOT "C" IN_LIST _languages)
    set(_ext "cpp")
    set(_lang CXX)
  endif()
  set(_line "${PROJECT_NAME}'s ${target} is a compiled program gazelle did not build: it needs ${reason}, "
    "which a gazelle venv does not have (no C++ ROS 2 or Gazebo libraries)")
  string(REPLACE ";" "" _line "${_line}")
  string(REPLACE "\\" "\\\\" _text "${_line}")
  string(REPLACE "\"" "\\\"" _text "${_text}")
  set(_source "${CMAKE_BINARY_DIR}/gazelle_placeholders/${target}.${_ext}")
  if(_type STREQUAL "EXECUTABLE")
    file(WRITE "${_source}" "#include <stdio.h>\nint main(void) {\n"
      "  fputs(\"gazelle: ${_text}\\n\", stderr);\n  return 1;\n}\n")
  else()
    string(MAKE_C_IDENTIFIER "${target}" _id)
    file(WRITE "${_source}" "/* gazelle: placeholder */\nint gazelle_placeholder_${_id} = 0;\n")
  endif()
  set_property(TARGET "${target}" PROPERTY SOURCES "${_source}")
  foreach(_property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES COMPILE_OPTIONS COMPILE_DEFINITIONS COMPILE_FEATURES
      INTERFACE_COMPILE_FEATURES INTERFACE_COMPILE_DEFINITIONS INTERFACE_COMPILE_OPTIONS INCLUDE_DIRECTORIES
      LINK_OPTIONS INTERFACE_LINK_OPTIONS LINK_DIRECTORIES INTERFACE_LINK_DIRECTORIES PRECOMPILE_HEADERS
      LINK_FLAGS)
    set_property(TARGET "${target}" PROPERTY ${_property} "")
  endforeach()
  set_target_properties("${target}" PROPERTIES LINKER_LANGUAGE ${_lang} AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
  message(NOTICE "gazelle: ${PROJECT_NAME}: ${target} is not built (it needs ${reason}, not available in a gazelle "
    "venv); the package's other files are installed")
endfunction()

function(gazelle_skip_unbuildable_targets)
  get_property(_targets GLOBAL PROPERTY GAZELLE_PROJECT_TARGETS)
  set(_skipped "")
  foreach(_target IN LISTS _targets)
    if(TARGET "${_target}")
      gazelle_cpp_target_unbuildable("${_target}" _reason)
      if(_reason)
        list(APPEND _skipped "${_target}")
        set("_reason_${_target}" "${_reason}")
      endif()
    endif()
  endforeach()
  # decided for every target first: a placeholder has no links, so deciding after would find it buildable
  foreach(_target IN LISTS _skipped)
    _gazelle_placeholder("${_target}" "${_reason_${_target}}")
  endforeach()
endfunction()

cmake_language(DEFER CALL gazelle_skip_unbuildable_targets)
