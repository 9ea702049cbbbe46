#error \
    "the panels draw with ImGui only: no OpenGL, glad, GLFW or ImGui backend headers here (see src/app/viewer/CMakeLists.txt)"
