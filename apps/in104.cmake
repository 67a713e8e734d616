# in104-render: the course-style example program of the IN 104 layer, built
# only against the handout's headers (raytrace::in104).
raytrace_add_program(in104-render in104-render.c LIBS raytrace::in104)
