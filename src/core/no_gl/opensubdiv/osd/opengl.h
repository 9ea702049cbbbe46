#error "sweep_core is GL-free: OpenSubdiv's Far layer only, no Osd GL glue"
