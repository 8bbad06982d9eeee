# Install pdfem into a temporary prefix, then build and run applications/examples/custom_program
# against it with find_package(pdfem), configured EXACTLY as its README says: Ninja, no
# CMAKE_BUILD_TYPE. The program must run both horizon factors, exit with 0 (a crash at exit is the
# sign of two deal.II libraries) and load only one deal.II library (ldd: libdeal.ii.so or
# libdeal.ii.g.so, never both). Last, a consumer that names a build type other than pdfem's
# (OTHER_BUILD_TYPE) must be refused at configure time with pdfemConfig.cmake's message.
#   cmake -DBUILD=... -DSOURCE=... -DWORK=... -DSCENE=... -DOTHER_BUILD_TYPE=... -P install_test.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# The README's reader has no build type in the environment either (CMake >= 3.22 reads it).
unset(ENV{CMAKE_BUILD_TYPE})

# cmake --install build --prefix $HOME/pdfem
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed")
endif()
# cmake -S applications/examples/custom_program -B build-custom -G Ninja -DCMAKE_PREFIX_PATH=$HOME/pdfem
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}/applications/examples/custom_program"
  -B "${WORK}/build-custom" -G Ninja -DCMAKE_PREFIX_PATH=${WORK}/prefix
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring against the installed pdfem failed:\n${out}\n${err}")
endif()
# cmake --build build-custom
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/build-custom" RESULT_VARIABLE rc
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building against the installed pdfem failed:\n${out}\n${err}")
endif()
set(program "${WORK}/build-custom/custom_program")

# Only one deal.II library among everything the program loads (its own and pdfem's dependencies:
# readelf -d would show only the program's direct ones), and a clean run. Both are checked and
# reported together.
set(failures "")
find_program(LDD ldd)
if(NOT LDD)
  message(FATAL_ERROR "ldd not found: cannot check which deal.II libraries custom_program loads")
endif()
execute_process(COMMAND ${LDD} "${program}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "ldd ${program} failed:\n${out}\n${err}")
endif()
string(REGEX MATCHALL "libdeal\\.ii(\\.g)?\\.so" deal_ii_libraries "${out}")
list(REMOVE_DUPLICATES deal_ii_libraries)
list(LENGTH deal_ii_libraries n)
if(n EQUAL 1)
  message("custom_program loads one deal.II library: ${deal_ii_libraries}")
else()
  string(APPEND failures "custom_program loads ${n} deal.II libraries (${deal_ii_libraries}), not one\n")
endif()

# build-custom/custom_program tests/scenes/patch_2d_quad.prm 3 4
execute_process(COMMAND "${program}" "${SCENE}" 3 4 WORKING_DIRECTORY "${WORK}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc STREQUAL "0")
  string(APPEND failures "custom_program exited with \"${rc}\" instead of 0\n")
endif()
if(NOT out MATCHES "m = 3: \"completed\"" OR NOT out MATCHES "m = 4: \"completed\"")
  string(APPEND failures "custom_program did not complete both runs\n")
endif()
if(failures)
  message(FATAL_ERROR "${failures}")
endif()

# Another build type than pdfem's: refused by find_package(pdfem), with the reason.
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}/applications/examples/custom_program"
  -B "${WORK}/build-other" -G Ninja -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=${OTHER_BUILD_TYPE}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc OR NOT err MATCHES "pdfem was built with CMAKE_BUILD_TYPE=")
  message(FATAL_ERROR "configuring with CMAKE_BUILD_TYPE=${OTHER_BUILD_TYPE} was not refused with "
    "pdfemConfig.cmake's message (exit ${rc}):\n${out}\n${err}")
endif()
message("CMAKE_BUILD_TYPE=${OTHER_BUILD_TYPE} refused as expected")
