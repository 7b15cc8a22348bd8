# femto_add_plugin(<name> <sources...>)
# Builds one plugin as its own shared library named <name>.so, linked against
# the femto core. Used in-tree and, through the installed femtoConfig.cmake,
# by plugins written outside the tree.
function(femto_add_plugin name)
  add_library(${name} MODULE ${ARGN})
  if(TARGET femto::core)
    target_link_libraries(${name} PRIVATE femto::core)
  else()
    target_link_libraries(${name} PRIVATE femto_core)
  endif()
  set_target_properties(${name} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${name}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  # A symbol the core does not export must fail the plugin's link, not the
  # dlopen of a scene that uses it later.
  target_link_options(${name} PRIVATE LINKER:--no-undefined)
  if(DEFINED FEMTO_PLUGIN_OUTPUT_DIR)
    set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${FEMTO_PLUGIN_OUTPUT_DIR})
    # In-tree: `femto_render` (make render) builds exactly these and the CLI.
    set_property(GLOBAL APPEND PROPERTY FEMTO_PLUGIN_TARGETS ${name})
  endif()
  if(DEFINED FEMTO_PLUGIN_INSTALL_DIR)
    install(TARGETS ${name} LIBRARY DESTINATION ${FEMTO_PLUGIN_INSTALL_DIR})
  endif()
endfunction()
