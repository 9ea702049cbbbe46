#pragma once
// What the panels' input fields hold between frames, one struct per panel that owns fields, so
// that a panel is handed its own (panels/panel_parts.hpp) and not the others'. PanelFields
// gathers them for the viewer's state.
#include "editor/view_state.hpp"

#include <array>
#include <cstdint>
#include <string>

namespace sweep::viewer {

/// A fixed-size text buffer for ImGui::InputText.
struct TextField {
  std::array<char, 1024> text{};
  void set(const std::string& value);
  std::string get() const { return text.data(); }
};

/// A number field being typed in (number_field.cpp): which one, its text, and where typing is.
struct TypedNumber {
  std::uint32_t id = 0;  // the field's ImGui id; 0: none is typed in
  TextField text;
  std::string initial;   // the text it started with (the value, exactly)
  bool focused = false;  // the text field has taken the keyboard (a frame after the click)
  int frame = -1;        // the ImGui frame it was last drawn in
};

/// The File panel's and the file dialogs' fields.
struct FileFields {
  TextField open;
  TextField save_as;
  TextField browser_filter;
  TextField export_prefix;
  TextField screenshot;
  double print_height_mm = 0.0;  // 3MF and STL: the printed model's height (0: 1 model unit = 1 mm)
};

/// The Material panel's fields.
struct MaterialFields {
  TextField material_name;     // a new material's name
  TextField material_texture;  // the shown material's texture and bump paths
  TextField material_bump;
  editor::ObjectId material_for = editor::kNoObject;  // the material those two fields show
};

/// The Edit panel's fields (its name row and the point table's split).
struct EditFields {
  TextField rename;
  editor::ObjectId rename_for = editor::kNoObject;  // the object whose name `rename` holds
  double split_t = 0.5;                             // where Split cuts a Bezier piece
};

/// The Create panel's fields.
struct CreateFields {
  bool frame_added = false;  // something was added: the main window frames the view on it (once)
  TextField curve_name;
  TextField surface_name;
  int template_choice = 0;
  int surface_choice = 0;   // 0: surface of revolution, 1: generalized cylinder, 2: birail
  int profile_choice = -1;  // object index
  int sweep_choice = -1;    // gcyl: the sweep; birail: the first rail
  int rail2_choice = -1;    // birail: the second rail
  int surface_steps = 24;
  TextField rider_name;
  int rider_path_choice = -1;   // object index of the curve ridden
  int rider_model_choice = -1;  // and of the surface carried
};

/// Every panel's fields, and the number being typed (any panel's).
struct PanelFields : FileFields, MaterialFields, EditFields, CreateFields {
  TypedNumber typed_number;
};

}  // namespace sweep::viewer
