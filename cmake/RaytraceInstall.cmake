# Install rules, the exported CMake package and raytrace.pc: filled in by the
# build's owner.
