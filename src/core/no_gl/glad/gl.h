#error "sweep_core is GL-free: no OpenGL, glad or GLFW headers here (see src/core/CMakeLists.txt)"
