cmake_minimum_required(VERSION 3.16)
# The structure of the source tree (ctest structure.modules):
#  - each module includes only the modules before it in PDFEM_MODULE_ORDER
#    (include/pdfem/<module>/ and source/<module>/ alike), so the include graph
#    has no cycle;
#  - no C++ file of the library, the applications or the tests is over 800 lines.
# Usage: cmake -DSOURCE=<checkout> -P check_structure.cmake
set(PDFEM_MODULE_ORDER base mesh pd fft pd_models fe solvers drivers coupling fracture io
    simulator postprocess scene)
set(failures "")
list(LENGTH PDFEM_MODULE_ORDER n_modules)
foreach(module ${PDFEM_MODULE_ORDER})
  list(FIND PDFEM_MODULE_ORDER ${module} rank)
  file(GLOB_RECURSE files ${SOURCE}/include/pdfem/${module}/*.h ${SOURCE}/include/pdfem/${module}/*.h.in
    ${SOURCE}/source/${module}/*.h ${SOURCE}/source/${module}/*.cc)
  foreach(f ${files})
    file(STRINGS ${f} includes REGEX "^#include [<\"]pdfem/[a-z_]+/")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include [<\"]pdfem/([a-z_]+)/.*" "\\1" used "${line}")
      list(FIND PDFEM_MODULE_ORDER ${used} used_rank)
      if(used_rank EQUAL -1)
        list(APPEND failures "${f}: includes the unknown module '${used}'")
      elseif(used_rank GREATER rank)
        list(APPEND failures "${f}: module ${module} includes ${used}, which comes after it")
      endif()
    endforeach()
  endforeach()
endforeach()
# Every folder of source/ is a module of the order.
file(GLOB folders LIST_DIRECTORIES true ${SOURCE}/source/*)
foreach(folder ${folders})
  if(IS_DIRECTORY ${folder})
    get_filename_component(name ${folder} NAME)
    list(FIND PDFEM_MODULE_ORDER ${name} found)
    if(found EQUAL -1)
      list(APPEND failures "source/${name}: a module missing from the order in check_structure.cmake")
    endif()
  endif()
endforeach()

file(GLOB_RECURSE cxx ${SOURCE}/source/*.cc ${SOURCE}/source/*.h ${SOURCE}/include/*.h
  ${SOURCE}/applications/*.cc ${SOURCE}/applications/*.h ${SOURCE}/tests/*.cc ${SOURCE}/tests/*.h)
foreach(f ${cxx})
  file(READ ${f} text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines n)
  if(n GREATER 800)
    list(APPEND failures "${f}: ${n} lines (at most 800)")
  endif()
endforeach()

if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "structure check failed:\n  ${text}")
endif()
message(STATUS "modules in order, files within 800 lines")
