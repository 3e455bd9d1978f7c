# sphkern_add_kernel_plugin(<name> SOURCES <files>...)
#
# Builds a kernel plugin: a module library named <name>.so with hidden visibility
# that sees only the plugin header, and installs it into sphkern's plugin folder.
# Used by sphkern's own plugins and, through find_package(sphkern), by third parties.
function(sphkern_add_kernel_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "sphkern_add_kernel_plugin(${name}): SOURCES is required")
  endif()
  add_library(${name} MODULE ${ARG_SOURCES})
  if(TARGET sphkern::plugin_sdk)
    target_link_libraries(${name} PRIVATE sphkern::plugin_sdk)
  else()
    target_link_libraries(${name} PRIVATE sphkern_plugin_sdk)
  endif()
  # Kernels are hot loops: optimised even when the project names no build type (-O3, as
  # -O2 does not take a loop's invariant branches out, and a kernel's sigma(dim) is one).
  target_compile_options(${name} PRIVATE $<$<STREQUAL:$<CONFIG>,>:-O3>)
  # No fused multiply-add contraction: the same results from every vector clone. No trapping
  # math: a branch-free ?: evaluates both pieces, and without it GCC keeps the branches (no
  # vector code) on instruction sets without masks, such as AVX2. sphkern never turns floating-point
  # exceptions into traps, so evaluating a piece it does not keep changes no result.
  target_compile_options(${name} PRIVATE
    $<$<OR:$<C_COMPILER_ID:GNU,Clang>,$<CXX_COMPILER_ID:GNU,Clang>>:-ffp-contract=off -fno-trapping-math>)
  set_target_properties(${name} PROPERTIES
    PREFIX ""
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(SPHKERN_BUILD_PLUGIN_DIR)
    set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${SPHKERN_BUILD_PLUGIN_DIR}")
  endif()
  if(NOT SPHKERN_PLUGIN_INSTALL_DIR)
    message(FATAL_ERROR "sphkern_add_kernel_plugin: SPHKERN_PLUGIN_INSTALL_DIR is not set")
  endif()
  install(TARGETS ${name} LIBRARY DESTINATION "${SPHKERN_PLUGIN_INSTALL_DIR}")
endfunction()
