# Helpers shared by pdfem's own build and by programs built against an installed pdfem.

# deal_ii_setup_target() adds deal.II's flags, include paths and libraries. Debian's deal.II adds -g to
# Release flags; debug info triples object sizes and costs ~20 % compile time, so Release targets drop it.
macro(pdfem_setup_target _target)
  deal_ii_setup_target(${_target})
  if(CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${_target} PRIVATE -g0)
  endif()
endmacro()

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
