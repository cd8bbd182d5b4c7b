# Tests of the mesh-topology filters (Module/): one C++ driver, no rendering.
# Included at the end of Testing/CMakeLists.txt.
set(filter_tests
  TestEdgeAdjacencyFilter
  TestLightSilhouetteFilter
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
