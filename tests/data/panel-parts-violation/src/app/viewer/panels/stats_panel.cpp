// A panel handed only its parts that reaches for the viewer's whole state (cmake/subfolders.cmake
// refuses it: tests/CMakeLists.txt's architecture.panel_parts).
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/viewer_state.hpp"
