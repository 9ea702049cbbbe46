#error \
    "src/geometry, model, io, editor and desktop are GL-free: no OpenGL, glad, GLFW, ImGui or OpenSubdiv GL headers here (docs/architecture.md)"
