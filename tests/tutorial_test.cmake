# The tutorials (applications/tutorials/step-N) built and run against an installed pdfem, EXACTLY as
# their README.md says, then a physical result of each checked.
#
#   cmake -DBUILD=<pdfem build> -DPREFIX=<prefix> -P tutorial_test.cmake
#       installs pdfem into PREFIX (a fresh one): the fixture of the tutorial tests;
#   cmake -DSOURCE=<checkout> -DPREFIX=<prefix> -DWORK=<scratch> -DTUTORIAL=step-N -DCHECKER=<pdfem_check>
#         -P tutorial_test.cmake
#       configures, builds and runs one tutorial.
#
# The README's build commands are run here as written, with $HOME/pdfem = PREFIX and the project folder's
# role played by WORK (build-step-N/ and output-step-N/ are made there). So that the two cannot drift apart,
# the README must contain each command line verbatim: if it changes, this test fails until it follows.
cmake_minimum_required(VERSION 3.16)
if(NOT TUTORIAL)
  # cmake --install build --prefix $HOME/pdfem
  file(REMOVE_RECURSE "${PREFIX}")
  execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${PREFIX}"
    RESULT_VARIABLE rc OUTPUT_QUIET)
  if(rc)
    message(FATAL_ERROR "cmake --install ${BUILD} --prefix ${PREFIX} failed")
  endif()
  message("pdfem installed into ${PREFIX}")
  return()
endif()

set(dir "${SOURCE}/applications/tutorials/${TUTORIAL}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# The README's reader has no build type in the environment either (CMake >= 3.22 reads it).
unset(ENV{CMAKE_BUILD_TYPE})

# ---- the README says these commands, word for word (first ```sh block, comments after '#' ignored)
set(commands
  "cmake --install build --prefix $HOME/pdfem"
  "cmake -S applications/tutorials/${TUTORIAL} -B build-${TUTORIAL} -G Ninja -DCMAKE_PREFIX_PATH=$HOME/pdfem"
  "cmake --build build-${TUTORIAL}"
  "build-${TUTORIAL}/${TUTORIAL}")
file(READ "${dir}/README.md" readme)
if(NOT readme MATCHES "```sh\n([^`]*)```")
  message(FATAL_ERROR "${dir}/README.md has no ```sh block with the commands to build and run it")
endif()
string(REPLACE "\n" ";" block "${CMAKE_MATCH_1}")
set(lines "")
foreach(line IN LISTS block)
  string(REGEX REPLACE "[ \t]+#.*$" "" line "${line}")
  string(STRIP "${line}" line)
  list(APPEND lines "${line}")
endforeach()
foreach(command IN LISTS commands)
  if(NOT command IN_LIST lines)
    message(FATAL_ERROR "${dir}/README.md does not say '${command}' in its ```sh block: the README and "
      "tests/tutorial_test.cmake must give the same commands (update both)")
  endif()
endforeach()

# ---- cmake -S applications/tutorials/step-N -B build-step-N -G Ninja -DCMAKE_PREFIX_PATH=$HOME/pdfem
execute_process(COMMAND ${CMAKE_COMMAND} -S "${dir}" -B "${WORK}/build-${TUTORIAL}" -G Ninja
  -DCMAKE_PREFIX_PATH=${PREFIX}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring ${TUTORIAL} against the installed pdfem failed:\n${out}\n${err}")
endif()
# ---- cmake --build build-step-N
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/build-${TUTORIAL}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building ${TUTORIAL} against the installed pdfem failed:\n${out}\n${err}")
endif()
# ---- build-step-N/step-N (from the folder that holds build-step-N)
execute_process(COMMAND "${WORK}/build-${TUTORIAL}/${TUTORIAL}" WORKING_DIRECTORY "${WORK}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc STREQUAL "0")
  message(FATAL_ERROR "${TUTORIAL} exited with \"${rc}\" instead of 0")
endif()

# ---- the results
set(output "${WORK}/output-${TUTORIAL}")
set(failures "")
# A check by pdfem_check on summary.json or history.csv (see tests/tools/pdfem_check.cc).
function(check)
  execute_process(COMMAND "${CHECKER}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  message("${o}${e}")
  if(rc)
    list(JOIN ARGN " " arguments)
    set(failures "${failures}failed: pdfem_check ${arguments}\n" PARENT_SCOPE)
  endif()
endfunction()
# A number the program printed: the first group of REGEX, within [LOW, HIGH].
function(check_printed what regex low high)
  if(NOT out MATCHES "${regex}")
    set(failures "${failures}${TUTORIAL} did not print ${what}\n" PARENT_SCOPE)
  elseif(NOT (CMAKE_MATCH_1 GREATER low AND CMAKE_MATCH_1 LESS high))
    set(failures "${failures}${what} = ${CMAKE_MATCH_1}, not within (${low}, ${high})\n" PARENT_SCOPE)
  else()
    message("${what} = ${CMAKE_MATCH_1}: within (${low}, ${high}): ok")
  endif()
endfunction()
# A text the program printed.
function(check_text what regex)
  if(NOT out MATCHES "${regex}")
    set(failures "${failures}${TUTORIAL} did not print ${what} ('${regex}')\n" PARENT_SCOPE)
  endif()
endfunction()

if(TUTORIAL STREQUAL "step-1")
  # The stress concentration factor of a hole with d/W = 0.1: Kirsch 3, Heywood 3.03; the run
  # gives 2.97 (the peak is smoothed over a horizon at the hole edge).
  check_printed("K_t" "K_t = sigma_max / sigma = ([0-9.]+)" 2.5 3.5)
  check(string "${output}/summary.json" exit_state completed)
  check(bound "${output}/summary.json" final.max_stress.xx > 1.75e7)
  check(bound "${output}/summary.json" final.max_stress.xx < 2.45e7)
elseif(TUTORIAL STREQUAL "step-2")
  # The program's criterion in the registry's listing, chosen by name, breaking bonds until the
  # plate is cut in two; at a load near LEFM's estimate t = 2.44 (the run: 2.85).
  check_text("its criterion in the registry" "\n  bond strain energy +\\(tutorial step-2\\)")
  check(string "${output}/summary.json" criterion "bond strain energy")
  check(string "${output}/summary.json" exit_state separated)
  check(bound "${output}/summary.json" final.bonds_broken_by_criterion > 0)
  check(bound "${output}/summary.json" final.load_factor > 1.5)
  check(bound "${output}/summary.json" final.load_factor < 3.5)
  check(nondecreasing "${output}/history.csv" n_broken_bonds)
  check(column "${output}/history.csv" max_energy_stretch_ratio max > 1)
  check_printed("the bonds the criterion broke" "criterion 'bond strain energy' broke ([0-9]+) bonds"
    0 1e9)
elseif(TUTORIAL STREQUAL "step-3")
  # The program's postprocessor in the registry's listing and in history.csv. The PD band
  # (0.05 m^3) is at rest until the wave arrives at 79 us; behind the wave, one-dimensional
  # theory gives 17.5 J (the run: a peak of 24 J at 175 us, from the strip's lateral motion);
  # the reflected wave leaves it nearly at rest by 314 us (the run: 1.9 J at the end).
  check_text("its postprocessor in the registry" "\n  pd kinetic energy +\\(tutorial step-3\\)")
  check_text("its postprocessor's line" "pd kinetic energy: peak")
  check(string "${output}/summary.json" exit_state completed)
  check(column "${output}/history.csv" kinetic_energy_pd max > 14)
  check(column "${output}/history.csv" kinetic_energy_pd last < 3.5)
  check(column "${output}/history.csv" kinetic_energy_fe max > 0)
  check(bound "${output}/summary.json" final.kinetic_energy_pd_max < 35)
  check(bound "${output}/summary.json" final.kinetic_energy_pd_max_time > 7.86e-5)
  check(bound "${output}/summary.json" final.kinetic_energy_pd_max_time < 3.14e-4)
else()
  message(FATAL_ERROR "tests/tutorial_test.cmake has no checks for ${TUTORIAL}: add them")
endif()
if(failures)
  message(FATAL_ERROR "${TUTORIAL}:\n${failures}")
endif()
message("${TUTORIAL}: built as its README says, ran, results within bounds")
