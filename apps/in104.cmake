# in104-render: the course-style example program of the IN 104 layer
# (issue 3), built only against the handout's headers (raytrace::in104).
add_executable(in104-render in104-render.c)
target_link_libraries(in104-render PRIVATE raytrace::in104)
raytrace_set_warnings(in104-render)
install(TARGETS in104-render RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
