#error "sweep_core and sweep_editor are GL-free: no ImGui here"
