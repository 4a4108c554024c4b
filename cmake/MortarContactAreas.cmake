# An "area" is one folder of sources (core/model, core/geometries, structural/elements...).
# Each becomes an OBJECT library mc_<name>; the shared core library is their union. Unit tests
# of one area link only the areas they need, so an area can be built and tested on its own.
set(MC_AREAS "" CACHE INTERNAL "")

function(mc_add_area name folder)
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${folder}/*.cpp)
  if(NOT srcs)
    set(srcs ${PROJECT_SOURCE_DIR}/cmake/empty_area.cpp)
  endif()
  add_library(mc_${name} OBJECT ${srcs})
  target_link_libraries(mc_${name} PUBLIC mc_build_settings mc_dependencies)
  target_compile_definitions(mc_${name} PRIVATE MC_BUILDING_CORE)
  set(MC_AREAS ${MC_AREAS} ${name} CACHE INTERNAL "")
endfunction()

# mc_add_unit_test(<name> [SOURCES <files...>] AREAS <areas...>)
# Without SOURCES, every *.cpp of the calling folder is a source of the test.
function(mc_add_unit_test name)
  cmake_parse_arguments(T "" "" "SOURCES;AREAS" ${ARGN})
  if(NOT T_SOURCES)
    file(GLOB T_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  endif()
  add_executable(${name} ${T_SOURCES})
  foreach(area IN LISTS T_AREAS)
    target_sources(${name} PRIVATE $<TARGET_OBJECTS:mc_${area}>)
  endforeach()
  target_link_libraries(${name} PRIVATE mc_build_settings mc_dependencies GTest::gtest_main)
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS unit)
endfunction()
