# numerics_add_plugin(NAME SOURCES...): a plugin for fluid_sim and fluid_sim_3d, the shared
# library lib<NAME>.so that a scene names under "plugins" (docs/extending.md). Its sources
# define NUMERICS_PLUGIN (app/plugin.hpp); only that entry point is exported.
function(numerics_add_plugin name)
  if(NOT ARGN)
    message(FATAL_ERROR "numerics_add_plugin(${name}): no source files given")
  endif()
  add_library(${name} MODULE ${ARGN})
  target_link_libraries(${name} PRIVATE numerics::app)
  set_target_properties(${name} PROPERTIES PREFIX "lib" CXX_VISIBILITY_PRESET hidden
                                           VISIBILITY_INLINES_HIDDEN ON)
endfunction()
