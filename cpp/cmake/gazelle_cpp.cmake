# gazelle's own build glue for the released ROS 2 sources vendored under cpp/ (see cpp/README.md): what
# every one of those packages shares. Included by each package's CMakeLists.txt after project().
#
# The packages build against the ROS 2 Jazzy wheels installed in the venv (their ament CMake configs under
# share/<pkg>/cmake) and install into it, so a workspace's `find_package(rclcpp)` finds them there as it
# finds rcl. scripts/build_cpp.sh configures them (prefix, flags, generator) and caches what they install.
if(NOT CMAKE_CXX_STANDARD)
  set(CMAKE_CXX_STANDARD 17)
  set(CMAKE_CXX_STANDARD_REQUIRED ON)
endif()
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
# shared libraries, as ament_cmake_ros makes them by default and as the binary packages ship them
set(BUILD_SHARED_LIBS ON)

# gazelle_cpp_library(NAME BUILDING_DEFINE [PUBLIC deps...] [PRIVATE deps...]): a shared library of every
# src/**/*.cpp of the package, its headers from include/ (installed into include/<project>, the Jazzy
# layout), exported as <project>::NAME.
function(gazelle_cpp_library name define)
  cmake_parse_arguments(ARG "" "" "PUBLIC;PRIVATE;SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    file(GLOB_RECURSE ARG_SOURCES CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp")
  endif()
  add_library(${name} SHARED ${ARG_SOURCES})
  target_compile_features(${name} PUBLIC cxx_std_17)
  # a dozen sources compiled as one file: the headers they share are parsed once for them all
  set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 12)
  target_compile_definitions(${name} PRIVATE "${define}")
  target_include_directories(${name} PUBLIC
    "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>"
    "$<BUILD_INTERFACE:${CMAKE_CURRENT_BINARY_DIR}/include>"
    "$<INSTALL_INTERFACE:include/${PROJECT_NAME}>")
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  install(TARGETS ${name} EXPORT ${PROJECT_NAME}
    ARCHIVE DESTINATION lib LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
endfunction()

# gazelle_cpp_headers(): the package's include/ (and generated headers in the build tree's include/)
# installed into include/<project>, and exported for old-style ${<pkg>_INCLUDE_DIRS} users.
function(gazelle_cpp_headers)
  install(DIRECTORY include/ DESTINATION include/${PROJECT_NAME})
  if(EXISTS "${CMAKE_CURRENT_BINARY_DIR}/include")
    install(DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/include/" DESTINATION include/${PROJECT_NAME})
  endif()
  ament_export_include_directories("include/${PROJECT_NAME}")
endfunction()
