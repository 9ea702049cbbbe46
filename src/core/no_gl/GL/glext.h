#error "sweep_core and sweep_editor are GL-free: no OpenGL, glad or GLFW headers here (see src/core/CMakeLists.txt)"
