# argine_room(NAME [DEPENDS room...]): builds src/NAME/*.cpp into the static library
# argine_NAME. Headers are under include/argine/NAME/. A room without sources becomes an
# interface library (header-only room), so rooms can be filled in one at a time.
set(ARGINE_ROOM_TARGETS "" CACHE INTERNAL "")
function(argine_room name)
  cmake_parse_arguments(ROOM "" "" "DEPENDS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/src/${name}/*.cpp")
  set(target argine_${name})
  set(deps "")
  foreach(dep IN LISTS ROOM_DEPENDS)
    list(APPEND deps argine_${dep})
  endforeach()
  if(sources)
    add_library(${target} STATIC ${sources})
    target_link_libraries(${target} PUBLIC ${deps} argine_deps PRIVATE argine_warnings)
    # sqrt, log, sin, exp without errno (argine never reads it after them): the same values,
    # but sqrt becomes one instruction without a branch to the library and the compiler may
    # treat the math functions as pure (hoist, merge repeated calls). Floating-point
    # operations that cannot trap (argine never enables traps): the same values again, but
    # the compiler may evaluate both sides of a branch and select, which is what lets it
    # vectorise a loop with branches (the time-step criteria, doc/scaling.md).
    target_compile_options(${target} PRIVATE -fno-math-errno -fno-trapping-math)
    target_include_directories(${target} PUBLIC
      $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
      $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  else()
    add_library(${target} INTERFACE)
    target_link_libraries(${target} INTERFACE ${deps} argine_deps)
    target_include_directories(${target} INTERFACE
      $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
      $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  endif()
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  set(ARGINE_ROOM_TARGETS ${ARGINE_ROOM_TARGETS} ${target} CACHE INTERNAL "")
endfunction()
