# Runs one scene test: cmake -DPDFEM=... -DCHECKER=... -DPRM=... -DWORK=... -DMPIEXEC=... -P run_scene_test.cmake
#
# Directives read from the scene's comments:
#   # CHECK: <json key> = <value> rel|abs <tol>   a value in summary.json
#   # CHECK: <json key> > <value>                  (or <) a bound on a value in summary.json
#   # CHECK-STRING: <json key> = <text>            a string in summary.json, equal to <text>
#   # CHECK-HISTORY: <command> <args>             pdfem_check <command> history.csv <args>
#                                                  (column ..., wave-speed ..., nondecreasing COLUMN;
#                                                  see pdfem_check.cc)
#   # EXIT-STATE: <state>                          expected exit_state (default completed)
#   # EXPECT-ERROR: <text>                         bad input: exit status 2 and one line
#                                                  "pdfem: error: ..." containing <text>
#   # MPI: <n> [<tol>]                             also run on n ranks: the same checks, and
#                                                  nodes.csv equal to the 1-rank one (1e-10, or
#                                                  <tol> where the scene says why its state is
#                                                  ill-conditioned)
#   # THREADS: 1                                   also run on one thread: nodes.csv and
#                                                  history.csv (but wall_seconds) equal to 1e-10
#   # REQUIRES: <path relative to the scene>      skip (not fail) when the path is absent
#   # REFERENCE: <scene relative to the scene>    run it once, for CHECK-REFERENCE
#   # CHECK-REFERENCE: <key> = <reference key> rel|abs <tol>
#                                                 a value against the reference run's value
#   # CHECK-REFERENCE-FIELDS: l2|max <columns> <tol>
#                                                 nodes.csv against the reference run's
#                                                 (pdfem_check fields)
cmake_minimum_required(VERSION 3.16)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{OMPI_MCA_rmaps_base_oversubscribe} 1)

file(STRINGS "${PRM}" directives REGEX "^# (CHECK|CHECK-STRING|CHECK-HISTORY|CHECK-REFERENCE|CHECK-REFERENCE-FIELDS|REFERENCE|EXIT-STATE|EXPECT-ERROR|MPI|THREADS|REQUIRES):")
get_filename_component(scene_dir "${PRM}" DIRECTORY)
set(checks "")
set(history_checks "")
set(string_checks "")
set(exit_state "completed")
set(expect_error "")
set(n_ranks 0)
set(mpi_tolerance 1e-10)
set(one_thread OFF)
set(reference "")
set(reference_checks "")
set(reference_field_checks "")
foreach(line IN LISTS directives)
  if(line MATCHES "^# CHECK-HISTORY: *([^ ]+) +(.+)$")
    set(command "${CMAKE_MATCH_1}")
    string(STRIP "${CMAKE_MATCH_2}" args)
    string(REGEX REPLACE " +" "|" args "${args}")
    list(APPEND history_checks "${command}|${args}")
  elseif(line MATCHES "^# CHECK-STRING: *([^ ]+) *= *(.+)$")
    string(STRIP "${CMAKE_MATCH_2}" text)
    list(APPEND string_checks "${CMAKE_MATCH_1}|${text}")
  elseif(line MATCHES "^# CHECK: *([^ ]+) *= *([^ ]+) +(rel|abs) +([^ ]+)")
    list(APPEND checks "${CMAKE_MATCH_1}|${CMAKE_MATCH_2}|${CMAKE_MATCH_3}|${CMAKE_MATCH_4}")
  elseif(line MATCHES "^# CHECK: *([^ ]+) *([<>]) *([^ ]+) *$")
    list(APPEND checks "${CMAKE_MATCH_1}|${CMAKE_MATCH_3}|${CMAKE_MATCH_2}|")
  elseif(line MATCHES "^# CHECK-REFERENCE-FIELDS: *(l2|max) +([^ ]+) +([^ ]+)")
    list(APPEND reference_field_checks "${CMAKE_MATCH_1}|${CMAKE_MATCH_2}|${CMAKE_MATCH_3}")
  elseif(line MATCHES "^# CHECK-REFERENCE: *([^ ]+) *= *([^ ]+) +(rel|abs) +([^ ]+)")
    list(APPEND reference_checks "${CMAKE_MATCH_1}|${CMAKE_MATCH_2}|${CMAKE_MATCH_3}|${CMAKE_MATCH_4}")
  elseif(line MATCHES "^# REFERENCE: *(.+)$")
    string(STRIP "${CMAKE_MATCH_1}" reference)
  elseif(line MATCHES "^# EXIT-STATE: *(.+)$")
    string(STRIP "${CMAKE_MATCH_1}" exit_state)
  elseif(line MATCHES "^# EXPECT-ERROR: *(.+)$")
    string(STRIP "${CMAKE_MATCH_1}" expect_error)
  elseif(line MATCHES "^# MPI: *([0-9]+) *([0-9.eE+-]*)")
    set(n_ranks ${CMAKE_MATCH_1})
    if(NOT "${CMAKE_MATCH_2}" STREQUAL "")
      set(mpi_tolerance ${CMAKE_MATCH_2})
    endif()
  elseif(line MATCHES "^# THREADS: *1 *$")
    set(one_thread ON)
  elseif(line MATCHES "^# REQUIRES: *(.+)$")
    string(STRIP "${CMAKE_MATCH_1}" required)
    if(NOT EXISTS "${scene_dir}/${required}")
      message("PDFEM_TEST_SKIPPED: ${scene_dir}/${required} is absent")
      return()
    endif()
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

if(expect_error)
  execute_process(COMMAND "${PDFEM}" "${PRM}" --output "${WORK}/out" --quiet
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${err}")
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "expected exit status 2 (bad input), got ${rc}")
  endif()
  string(STRIP "${err}" err_stripped)
  string(FIND "${err_stripped}" "\n" newline)
  if(NOT newline EQUAL -1 OR NOT err_stripped MATCHES "^pdfem: error: ")
    message(FATAL_ERROR "expected exactly one line 'pdfem: error: ...' on stderr")
  endif()
  string(FIND "${err}" "Stacktrace" stack_trace)
  if(NOT stack_trace EQUAL -1)
    message(FATAL_ERROR "the message must not carry a stack trace")
  endif()
  string(FIND "${err}" "${expect_error}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "the message does not mention '${expect_error}'")
  endif()
  if(EXISTS "${WORK}/out/history.csv")
    message(FATAL_ERROR "bad input must stop before any work, but history.csv was written")
  endif()
  return()
endif()

function(run_and_check tag launcher)
  execute_process(COMMAND ${launcher} "${PDFEM}" "${PRM}" --output "${WORK}/${tag}" --quiet
    --set "Output/Write nodes csv=true"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT EXISTS "${WORK}/${tag}/summary.json")
    message(FATAL_ERROR "${tag}: no summary.json (exit status ${rc})")
  endif()
  execute_process(COMMAND "${CHECKER}" string "${WORK}/${tag}/summary.json" exit_state "${exit_state}"
    RESULT_VARIABLE crc)
  set(failed ${crc})
  foreach(check IN LISTS checks)
    string(REPLACE "|" ";" parts "${check}")
    list(GET parts 0 key)
    list(GET parts 1 value)
    list(GET parts 2 kind)
    list(GET parts 3 tol)
    if(kind STREQUAL ">" OR kind STREQUAL "<")
      execute_process(COMMAND "${CHECKER}" bound "${WORK}/${tag}/summary.json" ${key} ${kind} ${value}
        RESULT_VARIABLE crc)
    else()
      execute_process(COMMAND "${CHECKER}" value "${WORK}/${tag}/summary.json" ${key} ${value} ${kind} ${tol}
        RESULT_VARIABLE crc)
    endif()
    if(crc)
      set(failed 1)
    endif()
  endforeach()
  foreach(check IN LISTS string_checks)
    string(FIND "${check}" "|" bar)
    string(SUBSTRING "${check}" 0 ${bar} key)
    math(EXPR bar "${bar} + 1")
    string(SUBSTRING "${check}" ${bar} -1 text)
    execute_process(COMMAND "${CHECKER}" string "${WORK}/${tag}/summary.json" ${key} "${text}"
      RESULT_VARIABLE crc)
    if(crc)
      set(failed 1)
    endif()
  endforeach()
  foreach(check IN LISTS history_checks)
    string(REPLACE "|" ";" parts "${check}")
    list(POP_FRONT parts command)
    execute_process(COMMAND "${CHECKER}" ${command} "${WORK}/${tag}/history.csv" ${parts}
      RESULT_VARIABLE crc)
    if(crc)
      set(failed 1)
    endif()
  endforeach()
  if(failed)
    message(FATAL_ERROR "${tag}: checks failed")
  endif()
endfunction()

# A reference scene, run once: CHECK-REFERENCE compares a value of this run with one of it.
if(reference)
  execute_process(COMMAND "${PDFEM}" "${scene_dir}/${reference}" --output "${WORK}/reference" --quiet
    --set "Output/Write nodes csv=true" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  foreach(check IN LISTS reference_checks)
    string(REPLACE "|" ";" parts "${check}")
    list(GET parts 0 key)
    list(GET parts 1 reference_key)
    list(GET parts 2 kind)
    list(GET parts 3 tol)
    execute_process(COMMAND "${CHECKER}" get "${WORK}/reference/summary.json" ${reference_key}
      RESULT_VARIABLE crc OUTPUT_VARIABLE value OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(crc)
      message(FATAL_ERROR "the reference ${reference} has no ${reference_key}")
    endif()
    message("reference ${reference_key} = ${value}")
    list(APPEND checks "${key}|${value}|${kind}|${tol}")
  endforeach()
endif()

# The files of run <tag> against the first run's, to <tol> (wall_seconds aside).
function(expect_same_as_np1 tag what tol)
  foreach(file IN LISTS ARGN)
    execute_process(COMMAND "${CHECKER}" csv "${WORK}/np1/${file}" "${WORK}/${tag}/${file}" ${tol}
      wall_seconds RESULT_VARIABLE crc)
    if(crc)
      message(FATAL_ERROR "the ${what} ${file} differs from the first run's")
    endif()
  endforeach()
endfunction()

run_and_check(np1 "")
foreach(check IN LISTS reference_field_checks)
  string(REPLACE "|" ";" parts "${check}")
  execute_process(COMMAND "${CHECKER}" fields "${WORK}/np1/nodes.csv" "${WORK}/reference/nodes.csv"
    ${parts} RESULT_VARIABLE crc)
  if(crc)
    message(FATAL_ERROR "the nodal fields differ from the reference ${reference}'s")
  endif()
endforeach()
if(n_ranks GREATER 1)
  run_and_check(np${n_ranks} "${MPIEXEC};-np;${n_ranks}")
  expect_same_as_np1(np${n_ranks} "${n_ranks}-rank" ${mpi_tolerance} nodes.csv)
endif()
if(one_thread)
  execute_process(COMMAND "${CHECKER}" get "${WORK}/np1/summary.json" threads
    OUTPUT_VARIABLE threads OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(threads LESS 2)
    message("note: the first run had ${threads} thread: nothing to compare the 1-thread run with")
  endif()
  run_and_check(threads1 "${CMAKE_COMMAND};-E;env;DEAL_II_NUM_THREADS=1")
  expect_same_as_np1(threads1 "1-thread" 1e-10 nodes.csv history.csv)
endif()
