# Small helpers shared by the CMakeLists of the tree.

# topay_add_library(NAME SOURCES... [DEPS deps...])
# A static library whose public include root is the repository root, so headers are included
# as "core/robot/kinematics.h".
function(topay_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_SOURCES)  # headers only (or not written yet)
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARG_DEPS})
    return()
  endif()
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# topay_add_gtest(SOURCE DEPS deps...)   (SOURCE: absolute path of a tests/**/*_test.cc)
# One test executable per test file, named after the file; its tests are registered with
# ctest one by one (gtest_discover_tests), labelled with the folder under tests/, e.g.
# "core/planning"; the cases matched by the gtest filter TOPAY_LONG_TESTS_<name> (set by
# tests/CMakeLists.txt: the 100-task runs and the harness's smoke runs) get "long/<folder>"
# instead. `ctest -LE ^long` runs the fast suite, `ctest -L ^long` the long one; CI runs all.
# (One label per test: gtest_discover_tests does not pass a list of labels through.)
function(topay_add_gtest source)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  get_filename_component(name ${source} NAME_WE)
  get_filename_component(dir ${source} DIRECTORY)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR}/tests ${dir})
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    TOPAY_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    TOPAY_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(DEFINED TOPAY_LONG_TESTS_${name})
    set(long_filter "${TOPAY_LONG_TESTS_${name}}")
    gtest_discover_tests(${name} TEST_FILTER "-${long_filter}"
      PROPERTIES LABELS "${rel}" DISCOVERY_TIMEOUT 60)
    gtest_discover_tests(${name} TEST_FILTER "${long_filter}"
      PROPERTIES LABELS "long/${rel}" DISCOVERY_TIMEOUT 60)
  else()
    gtest_discover_tests(${name} PROPERTIES LABELS "${rel}" DISCOVERY_TIMEOUT 60)
  endif()
endfunction()
