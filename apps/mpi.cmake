# rt-export-mpi, rendering over MPI (docs/mpi.md): built when
# RAYTRACE_MPI is ON, or AUTO and CMake's FindMPI finds MPI's C bindings
# (Debian: libopenmpi-dev).  The library never depends on MPI: only this
# program links it.
set(RAYTRACE_MPI AUTO CACHE STRING
  "Build rt-export-mpi, the renderer over MPI (AUTO, ON, OFF)")
set_property(CACHE RAYTRACE_MPI PROPERTY STRINGS AUTO ON OFF)

if(RAYTRACE_MPI STREQUAL "ON")
  find_package(MPI REQUIRED COMPONENTS C)
elseif(RAYTRACE_MPI STREQUAL "AUTO")
  find_package(MPI QUIET COMPONENTS C)
endif()
find_package(Threads)

if(MPI_C_FOUND AND Threads_FOUND)
  if(COMMAND raytrace_add_program)
    raytrace_add_program(rt-export-mpi rt-export-mpi.c mpi/farm.c mpi/share.c
      LIBS raytrace_cli MPI::MPI_C Threads::Threads)
  else()
    add_executable(raytrace_rt_export_mpi rt-export-mpi.c mpi/farm.c mpi/share.c)
    set_target_properties(raytrace_rt_export_mpi PROPERTIES
      OUTPUT_NAME rt-export-mpi)
    target_link_libraries(raytrace_rt_export_mpi PRIVATE raytrace_cli
      MPI::MPI_C Threads::Threads)
    raytrace_set_warnings(raytrace_rt_export_mpi)
    install(TARGETS raytrace_rt_export_mpi
      RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
  target_include_directories(raytrace_rt_export_mpi PRIVATE
    "${CMAKE_CURRENT_SOURCE_DIR}/mpi")
  target_compile_definitions(raytrace_rt_export_mpi PRIVATE
    _POSIX_C_SOURCE=200809L)
  message(STATUS "rt-export-mpi: MPI ${MPI_C_VERSION} found")
elseif(NOT RAYTRACE_MPI STREQUAL "OFF")
  message(STATUS "rt-export-mpi disabled: MPI not found "
                 "(Debian: apt-get install libopenmpi-dev openmpi-bin)")
endif()
raytrace_feature_info(mpi "TARGET raytrace_rt_export_mpi"
  "rt-export-mpi, rendering over MPI (RAYTRACE_MPI)")
