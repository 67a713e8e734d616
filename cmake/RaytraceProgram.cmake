# raytrace_add_program(<file-name> <source>... [LIBS <lib>...] [NO_INSTALL]):
# a program of the project.  Its target carries the project's prefix,
# raytrace_<file_name> (rt-export -> raytrace_rt_export), so that it never
# collides with a target of a parent project; the file keeps its name
# (OUTPUT_NAME).  Every program of apps/ lands in the build's apps/ (the
# handout's `build/apps/rt-export`), every one of tools/ in tools/,
# whatever folder its sources have.  Installed into bin/ when
# RAYTRACE_INSTALL and RAYTRACE_APPS are on, unless NO_INSTALL.
function(raytrace_add_program name)
  cmake_parse_arguments(ARG "NO_INSTALL" "" "LIBS" ${ARGN})
  string(REPLACE "-" "_" target "raytrace_${name}")
  add_executable(${target} ${ARG_UNPARSED_ARGUMENTS})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME "${name}")
  file(RELATIVE_PATH _rt_where "${PROJECT_SOURCE_DIR}"
       "${CMAKE_CURRENT_SOURCE_DIR}")
  string(REGEX MATCH "^(apps|tools)" _rt_top "${_rt_where}")
  if(_rt_top)
    set_target_properties(${target} PROPERTIES
      RUNTIME_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/${_rt_top}")
  endif()
  target_link_libraries(${target} PRIVATE ${ARG_LIBS})
  raytrace_set_warnings(${target})
  if(RAYTRACE_INSTALL AND RAYTRACE_APPS AND NOT ARG_NO_INSTALL)
    install(TARGETS ${target} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
  endif()
endfunction()
