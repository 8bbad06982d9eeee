# Round trip of pdfem-convert on one PDLSM-FEM command file:
#   cmake -DPDFEM=... -DCONVERT=... -DCHECKER=... -DIN=model.in -DWORK=... -DTOL=1e-10
#         -P run_convert_test.cmake
#
# 1. pdfem model.in (the reference run);
# 2. pdfem-convert model.in --output WORK/converted;
# 3. if step 1 was bad input (exit status 2): the converter must fail the same way, with the
#    same one-line message ("pdfem-convert: error: " instead of "pdfem: error: ") and write
#    no .prm; otherwise pdfem WORK/converted/model.prm, and history.csv, nodes.csv and
#    summary.json must agree with the reference run to TOL (pdfem_check csv / summaries).
#
# Directives read from the command file's comments:
#   # REQUIRES: <path relative to the file>      skip (not fail) when the path is absent
#   # CONVERT-ERROR: <text>                      a model that pdfem runs but a .prm cannot express:
#                                                the converter must exit with status 2 and one line
#                                                "pdfem-convert: error: ..." containing <text>, and
#                                                write no .prm
cmake_minimum_required(VERSION 3.16)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)

get_filename_component(in_dir "${IN}" DIRECTORY)
get_filename_component(name "${IN}" NAME_WE)
file(STRINGS "${IN}" directives REGEX "^# (REQUIRES|CONVERT-ERROR):")
set(convert_error "")
foreach(line IN LISTS directives)
  if(line MATCHES "^# CONVERT-ERROR: *(.+)$")
    string(STRIP "${CMAKE_MATCH_1}" convert_error)
  elseif(line MATCHES "^# REQUIRES: *(.+)$")
    string(STRIP "${CMAKE_MATCH_1}" required)
    if(NOT EXISTS "${in_dir}/${required}")
      message("PDFEM_TEST_SKIPPED: ${in_dir}/${required} is absent")
      return()
    endif()
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

if(convert_error)
  execute_process(COMMAND "${CONVERT}" "${IN}" --output "${WORK}/converted"
    RESULT_VARIABLE rc_c OUTPUT_VARIABLE out_c ERROR_VARIABLE err_c)
  message("pdfem-convert: exit status ${rc_c}\n${out_c}${err_c}")
  string(STRIP "${err_c}" e_c)
  string(FIND "${e_c}" "\n" newline)
  string(FIND "${e_c}" "${convert_error}" found)
  if(NOT rc_c EQUAL 2 OR NOT newline EQUAL -1 OR NOT e_c MATCHES "^pdfem-convert: error: "
     OR found EQUAL -1)
    message(FATAL_ERROR "expected exit status 2 and one line 'pdfem-convert: error: ...' "
      "containing '${convert_error}'")
  endif()
  if(EXISTS "${WORK}/converted/${name}.prm" OR EXISTS "${WORK}/converted/${name}.msh")
    message(FATAL_ERROR "the model cannot be expressed, but files were written")
  endif()
  return()
endif()

# 1. the reference run
execute_process(COMMAND "${PDFEM}" "${IN}" --output "${WORK}/in" --quiet
  --set "Output/Write nodes csv=true" --set "Output/Write vtu=false"
  RESULT_VARIABLE rc_in OUTPUT_VARIABLE out ERROR_VARIABLE err_in)
message("pdfem ${name}.in: exit status ${rc_in}\n${err_in}")

# 2. the conversion
execute_process(COMMAND "${CONVERT}" "${IN}" --output "${WORK}/converted"
  RESULT_VARIABLE rc_c OUTPUT_VARIABLE out_c ERROR_VARIABLE err_c)
message("pdfem-convert: exit status ${rc_c}\n${out_c}${err_c}")

if(rc_in EQUAL 2)
  if(NOT rc_c EQUAL 2)
    message(FATAL_ERROR "pdfem rejects the input, but pdfem-convert exited with ${rc_c}")
  endif()
  string(STRIP "${err_in}" e_in)
  string(STRIP "${err_c}" e_c)
  string(REGEX REPLACE "^pdfem: error: " "" m_in "${e_in}")
  string(REGEX REPLACE "^pdfem-convert: error: " "" m_c "${e_c}")
  if(m_in STREQUAL e_in OR m_c STREQUAL e_c OR NOT m_in STREQUAL m_c)
    message(FATAL_ERROR "the messages differ:\n  ${e_in}\n  ${e_c}")
  endif()
  if(EXISTS "${WORK}/converted/${name}.prm")
    message(FATAL_ERROR "bad input, but ${name}.prm was written")
  endif()
  return()
endif()
if(NOT rc_c EQUAL 0)
  message(FATAL_ERROR "pdfem-convert failed (exit status ${rc_c})")
endif()
if(NOT EXISTS "${WORK}/in/summary.json")
  message(FATAL_ERROR "the reference run wrote no summary.json (exit status ${rc_in})")
endif()

# 3. the converted scene
execute_process(COMMAND "${PDFEM}" "${WORK}/converted/${name}.prm" --output "${WORK}/prm" --quiet
  --set "Output/Write nodes csv=true" --set "Output/Write vtu=false"
  RESULT_VARIABLE rc_prm OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("pdfem ${name}.prm: exit status ${rc_prm}\n${err}")
if(NOT rc_prm EQUAL rc_in)
  message(FATAL_ERROR "exit status ${rc_prm} from the .prm, ${rc_in} from the .in")
endif()
set(failed 0)
foreach(csv history.csv nodes.csv)
  execute_process(COMMAND "${CHECKER}" csv "${WORK}/in/${csv}" "${WORK}/prm/${csv}" ${TOL}
    wall_seconds
    RESULT_VARIABLE crc OUTPUT_VARIABLE out)
  message("${csv}:\n${out}")
  if(crc)
    set(failed 1)
  endif()
endforeach()
execute_process(COMMAND "${CHECKER}" summaries "${WORK}/in/summary.json" "${WORK}/prm/summary.json"
  ${TOL} RESULT_VARIABLE crc OUTPUT_VARIABLE out)
message("summary.json:\n${out}")
if(crc)
  set(failed 1)
endif()
file(STRINGS "${WORK}/in/history.csv" rows)
list(LENGTH rows n_rows)
if(n_rows LESS 2)
  message(FATAL_ERROR "history.csv has no rows")
endif()
if(failed)
  message(FATAL_ERROR "the converted scene gives different results")
endif()
