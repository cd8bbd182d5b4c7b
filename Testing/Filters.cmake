# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Tests of the mesh-topology filters (Module/): one C++ driver, no rendering,
# and Python tests of the same filters through the vtksoftshadows package.
# Included at the end of Testing/CMakeLists.txt.
set(filter_tests
  TestEdgeAdjacencyFilter
  TestLightSilhouetteFilter
  TestMeshFiltersRobustness
  TestTopologyAwareMeshFilter)
create_test_sourcelist(filter_driver_sources SoftShadowsFiltersCxxTests.cxx ${filter_tests})
list(TRANSFORM filter_tests APPEND ".cxx" OUTPUT_VARIABLE filter_test_sources)
list(TRANSFORM filter_test_sources PREPEND "Cxx/Filters/")
add_executable(SoftShadowsFiltersCxxTests SoftShadowsFiltersCxxTests.cxx ${filter_test_sources})
target_include_directories(SoftShadowsFiltersCxxTests PRIVATE Cxx/Filters)
target_link_libraries(SoftShadowsFiltersCxxTests PRIVATE
  SoftShadows::Filters
  VTK::CommonCore
  VTK::CommonDataModel
  VTK::FiltersCore
  VTK::FiltersSources
  VTK::RenderingCore
  glm::glm)
foreach (test IN LISTS filter_tests)
  add_test(NAME "Cxx.Filters.${test}" COMMAND SoftShadowsFiltersCxxTests ${test})
endforeach ()
# The silhouette searches once more on one thread: results must not depend on
# the SMP backend (Debian's default is TBB).
add_test(NAME "Cxx.Filters.TestLightSilhouetteFilter.Sequential"
  COMMAND SoftShadowsFiltersCxxTests TestLightSilhouetteFilter)
set_tests_properties("Cxx.Filters.TestLightSilhouetteFilter.Sequential" PROPERTIES
  ENVIRONMENT "VTK_SMP_BACKEND_IN_USE=Sequential")

set(filter_python_tests
  test_mesh_filters)
foreach (test IN LISTS filter_python_tests)
  add_test(NAME "Python.${test}"
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/${test}.py")
  set_tests_properties("Python.${test}" PROPERTIES
    ENVIRONMENT "PYTHONPATH=${SOFTSHADOWS_PYTHONPATH}:${CMAKE_CURRENT_SOURCE_DIR}/Python")
endforeach ()
