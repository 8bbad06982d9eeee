# Install pdfem into a temporary prefix, build applications/examples/custom_program against it with
# find_package(pdfem), and run it on a patch scene.
#   cmake -DBUILD=... -DSOURCE=... -DWORK=... -DSCENE=... -P install_test.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}/applications/examples/custom_program"
  -B "${WORK}/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK}/prefix
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring against the installed pdfem failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/build" RESULT_VARIABLE rc
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building against the installed pdfem failed:\n${out}\n${err}")
endif()
execute_process(COMMAND "${WORK}/build/custom_program" "${SCENE}" 3 4 WORKING_DIRECTORY "${WORK}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(rc OR NOT out MATCHES "m = 3: \"completed\"" OR NOT out MATCHES "m = 4: \"completed\"")
  message(FATAL_ERROR "custom_program did not complete both runs")
endif()
