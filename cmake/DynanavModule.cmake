# dynanav_module(NAME DEPS dep1 dep2 ... [LIBS extra libraries])
# One folder under src/ = one static library `dynanav_<NAME>`. Sources are the folder's .cpp files
# (recursively), so adding a file needs no CMake edit. DEPS names other dynanav modules.
function(dynanav_module NAME)
  cmake_parse_arguments(ARG "" "" "DEPS;LIBS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  set(dep_targets)
  foreach(dep IN LISTS ARG_DEPS)
    list(APPEND dep_targets dynanav_${dep})
  endforeach()
  if(NOT sources)  # a module that is only headers so far
    add_library(dynanav_${NAME} INTERFACE)
    target_include_directories(dynanav_${NAME} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(dynanav_${NAME} INTERFACE ${dep_targets} ${ARG_LIBS})
    return()
  endif()
  add_library(dynanav_${NAME} STATIC ${sources})
  target_include_directories(dynanav_${NAME} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(dynanav_${NAME} PUBLIC ${dep_targets} ${ARG_LIBS})
  target_compile_options(dynanav_${NAME} PRIVATE -Wall -Wextra)
  set_property(GLOBAL APPEND PROPERTY DYNANAV_MODULES dynanav_${NAME})
endfunction()

# dynanav_test(MODULE LABEL) — one GoogleTest executable per module and label from
# tests/<MODULE>/*.cpp (label unit) or tests/<MODULE>/<LABEL>/*.cpp.
# Tests that need ../shared call GTEST_SKIP() with a message; ctest reports them as skipped.
function(dynanav_test MODULE LABEL)
  if(LABEL STREQUAL "unit")
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${MODULE}/*.cpp)
    set(exe test_${MODULE})
  else()
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${MODULE}/${LABEL}/*.cpp)
    set(exe test_${MODULE}_${LABEL})
  endif()
  if(NOT sources)
    return()
  endif()
  add_executable(${exe} ${sources})
  # A suite links only its own module (and what that depends on), so a broken module elsewhere
  # does not stop it; suites that run the CLI also make sure it is built.
  target_link_libraries(${exe} PRIVATE dynanav_test_support dynanav_${MODULE} ${ARGN} GTest::gtest_main GTest::gmock)
  if(NOT LABEL STREQUAL "unit")
    add_dependencies(${exe} dynanav_cli)
  endif()
  target_compile_options(${exe} PRIVATE -Wall -Wextra)
  gtest_discover_tests(${exe}
    TEST_PREFIX "${MODULE}."
    PROPERTIES LABELS ${LABEL} SKIP_REGULAR_EXPRESSION "\\[  SKIPPED \\]"
    DISCOVERY_TIMEOUT 60)
endfunction()
