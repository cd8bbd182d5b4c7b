# The installed module as an outside project sees it: install this build
# into a fresh prefix, build Examples/Cxx/OutOfTree (a technique written
# against the installed framework headers) with find_package(SoftShadows),
# and run it. Run as
#   cmake -DBUILD=<build tree> -DSOURCE=<example> -DWORK=<scratch> -P OutOfTree.cmake
file(REMOVE_RECURSE "${WORK}")
function (run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${what}: ${out}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}):\n${out}\n${err}")
  endif ()
endfunction ()
run("install" "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/prefix")
run("configure" "${CMAKE_COMMAND}" -S "${SOURCE}" -B "${WORK}/build"
  "-DCMAKE_PREFIX_PATH=${WORK}/prefix" -DCMAKE_BUILD_TYPE=Release)
run("build" "${CMAKE_COMMAND}" --build "${WORK}/build")
run("TexelGrid" "${WORK}/build/TexelGrid" "${WORK}/grid.png")
