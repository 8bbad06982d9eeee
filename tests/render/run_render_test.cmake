# One render.* test (tests/render/CMakeLists.txt):
#   cmake -DRENDER=pdfem-render -DWORK=dir -DARGS="a##b##..." [options] -P run_render_test.cmake
# (RENDER is the program to run: pdfem-render, or pdfem-plot for render.chart_overlay)
#
#   -DPDFEM=pdfem -DSCENE=x.prm   first run pdfem on the scene into WORK (the fixture's setup;
#                                 nothing else is done then)
#   -DPREPARE=three_steps         write WORK/three_steps.pvd: the dataset of INPUT three times,
#                                 at times 0, 0.5 and 1
#   -DPREPARE=no_cracked          copy INPUT's .pvtu and .vtu into WORK/no_cracked/ without the
#                                 cell array "cracked" (a file of pdfem before 2026-11-25)
#   -DEXPECT_RC=0|2               exit status of pdfem-render (default 0)
#   -DSTDOUT="re1##re2"           regular expressions stdout must match (each on its own)
#   -DSTDERR="re"                 for EXPECT_RC=2: stderr must be one line matching re
#   -DCHECKER=check_png -DPNG=file -DPNG_SIZE="W H" -DMIN_COLOURS="n [P%] [R,G,B ...]"
#                                 then check the picture (see check_png.cc)
#   -DXVFB_RUN=xvfb-run           used when DISPLAY is not set (pdfem-render draws through X)
# "##" separates list items, because ';' would split the arguments of add_test.
cmake_minimum_required(VERSION 3.16)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)

if(DEFINED SCENE)
  file(REMOVE_RECURSE "${WORK}")
  execute_process(COMMAND "${PDFEM}" "${SCENE}" --output "${WORK}" --quiet
                          --set "Output/Write vtu=true"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pdfem ${SCENE} failed (${rc}):\n${out}\n${err}")
  endif()
  return()
endif()

file(MAKE_DIRECTORY "${WORK}")
if(PREPARE STREQUAL "three_steps")
  file(WRITE "${WORK}/three_steps.pvd"
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n"
    "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"${INPUT}\"/>\n"
    "    <DataSet timestep=\"0.5\" group=\"\" part=\"0\" file=\"${INPUT}\"/>\n"
    "    <DataSet file=\"${INPUT}\" timestep=\"1\"/>\n"
    "  </Collection>\n</VTKFile>\n")
elseif(PREPARE STREQUAL "no_cracked")
  # The .pvtu and its pieces, each without the DataArray (or PDataArray) named "cracked".
  get_filename_component(folder "${INPUT}" DIRECTORY)
  get_filename_component(name "${INPUT}" NAME_WE)
  file(GLOB files "${folder}/${name}.pvtu" "${folder}/${name}.*.vtu")
  file(MAKE_DIRECTORY "${WORK}/no_cracked")
  foreach(f ${files})
    file(READ "${f}" text)
    string(REGEX REPLACE "<PDataArray[^>]*Name=\"cracked\"[^>]*/>" "" text "${text}")
    string(REGEX REPLACE "<DataArray[^>]*Name=\"cracked\"[^>]*>[^<]*</DataArray>" "" text "${text}")
    if(text MATCHES "Name=\"cracked\"")
      message(FATAL_ERROR "could not remove the array 'cracked' from ${f}")
    endif()
    get_filename_component(base "${f}" NAME)
    file(WRITE "${WORK}/no_cracked/${base}" "${text}")
  endforeach()
endif()

string(REPLACE "##" ";" args "${ARGS}")
set(command "${RENDER}" ${args})
if(NOT EXPECT_RC)
  set(EXPECT_RC 0)
endif()
if(EXPECT_RC EQUAL 0 AND "$ENV{DISPLAY}" STREQUAL "")
  if(NOT XVFB_RUN)
    message("PDFEM_TEST_SKIPPED: no X display and no xvfb-run (apt-get install xvfb xauth)")
    return()
  endif()
  set(command "${XVFB_RUN}" -a ${command})
endif()
execute_process(COMMAND ${command} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL EXPECT_RC)
  get_filename_component(program "${RENDER}" NAME)
  message(FATAL_ERROR "${program} exited with ${rc}, expected ${EXPECT_RC}")
endif()

if(STDOUT)
  string(REPLACE "##" ";" patterns "${STDOUT}")
  foreach(pattern ${patterns})
    if(NOT out MATCHES "${pattern}")
      message(FATAL_ERROR "stdout does not match '${pattern}'")
    endif()
  endforeach()
endif()
if(EXPECT_RC EQUAL 2)
  string(STRIP "${err}" line)
  get_filename_component(program "${RENDER}" NAME)
  string(REPLACE "_" "-" program "${program}")
  if(line MATCHES "\n" OR NOT line MATCHES "^${program}: error: ")
    message(FATAL_ERROR "expected one line '${program}: error: ...' on stderr, got:\n${err}")
  endif()
  if(STDERR AND NOT line MATCHES "${STDERR}")
    message(FATAL_ERROR "stderr does not match '${STDERR}'")
  endif()
endif()

if(PNG)
  separate_arguments(size UNIX_COMMAND "${PNG_SIZE}")
  separate_arguments(colours UNIX_COMMAND "${MIN_COLOURS}")
  execute_process(COMMAND "${CHECKER}" "${PNG}" ${size} ${colours}
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the picture failed its checks")
  endif()
endif()
