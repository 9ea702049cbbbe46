#error "sweep_core is GL-free: no ImGui here"
