# Helpers shared by pdfem's own build and by programs built against an installed pdfem.

# deal.II comes as two libraries, DEBUG (libdeal.ii.g.so) and RELEASE (libdeal.ii.so), and
# deal_ii_setup_target() picks one from CMAKE_BUILD_TYPE. A program must link the one pdfem links:
# with both, it runs two copies of deal.II and crashes at exit. PDFEM_DEAL_II_BUILD (DEBUG or RELEASE)
# fixes the choice: pdfem's build sets it from the library (pdfem_deal_ii_build), and
# pdfemConfig.cmake to what the installed library links. Unset, deal.II decides.
#
# deal_ii_setup_target() adds deal.II's flags, include paths and libraries. Debian's deal.II adds -g to
# Release flags; debug info triples object sizes and costs ~20 % compile time, so Release targets drop it.
macro(pdfem_setup_target _target)
  deal_ii_setup_target(${_target} ${PDFEM_DEAL_II_BUILD})
  if(CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${_target} PRIVATE -g0)
  endif()
  if(PDFEM_SANITIZE)
    target_compile_options(${_target} PRIVATE -fsanitize=${PDFEM_SANITIZE} -fno-omit-frame-pointer
                                              -fno-sanitize-recover=all)
    target_link_options(${_target} PRIVATE -fsanitize=${PDFEM_SANITIZE})
  endif()
endmacro()

# The deal.II library a target set up by pdfem_setup_target links, DEBUG or RELEASE, into <_out>.
function(pdfem_deal_ii_build _out _target)
  get_target_property(_libraries ${_target} LINK_LIBRARIES)
  if(DEAL_II_TARGET_DEBUG AND NOT DEAL_II_TARGET_DEBUG STREQUAL DEAL_II_TARGET_RELEASE
     AND DEAL_II_TARGET_DEBUG IN_LIST _libraries)
    set(${_out} DEBUG PARENT_SCOPE)
  else()
    set(${_out} RELEASE PARENT_SCOPE)
  endif()
endfunction()

# An executable written against the library: add_executable + deal.II set-up + link to pdfem.
macro(pdfem_add_executable _target)
  add_executable(${_target} ${ARGN})
  pdfem_setup_target(${_target})
  if(TARGET pdfem::pdfem)
    target_link_libraries(${_target} pdfem::pdfem)
    # deal.II's set-up leaves the run path to its own libraries only: add pdfem's.
    get_target_property(_pdfem_location pdfem::pdfem LOCATION)
    get_filename_component(_pdfem_libdir "${_pdfem_location}" DIRECTORY)
    set_property(TARGET ${_target} APPEND PROPERTY BUILD_RPATH "${_pdfem_libdir}")
    set_property(TARGET ${_target} APPEND PROPERTY INSTALL_RPATH "${_pdfem_libdir}")
  else()
    target_link_libraries(${_target} pdfem)
  endif()
endmacro()
