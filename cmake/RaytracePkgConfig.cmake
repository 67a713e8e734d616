# raytrace_install_pkgconfig(<name> <template>): writes <name>.pc from
# <template> into the build tree and installs it into <libdir>/pkgconfig
# (when RAYTRACE_INSTALL is on).  The one place that decides what every .pc
# file of the project says about where things are: the template gets
#   @RAYTRACE_PC_PREFIX@      relocatable, ${pcfiledir}/.. (or the absolute
#                             prefix when the pkgconfig directory is absolute)
#   @RAYTRACE_PC_LIBDIR@      ${prefix}/<libdir>
#   @RAYTRACE_PC_INCLUDEDIR@  ${prefix}/<includedir>
# and every variable of the caller (PROJECT_VERSION, ...), so a tree
# installed with `cmake --install build --prefix DIR`, or moved, still works.
function(raytrace_install_pkgconfig name template)
  set(pc_dir "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
  if(IS_ABSOLUTE "${pc_dir}")
    set(RAYTRACE_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  else()
    file(RELATIVE_PATH up "/prefix/${pc_dir}" "/prefix")
    string(REGEX REPLACE "/$" "" up "${up}")
    set(RAYTRACE_PC_PREFIX "\${pcfiledir}/${up}")
  endif()
  foreach(dir LIBDIR INCLUDEDIR)
    if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
      set(RAYTRACE_PC_${dir} "${CMAKE_INSTALL_${dir}}")
    else()
      set(RAYTRACE_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
    endif()
  endforeach()
  configure_file("${template}" "${PROJECT_BINARY_DIR}/${name}.pc" @ONLY)
  if(RAYTRACE_INSTALL)
    install(FILES "${PROJECT_BINARY_DIR}/${name}.pc" DESTINATION "${pc_dir}")
  endif()
endfunction()
