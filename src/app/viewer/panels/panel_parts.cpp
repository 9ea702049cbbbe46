#include "app/viewer/panels/panel_parts.hpp"

#include "app/viewer/viewer_state.hpp"

namespace sweep::viewer::panels {

ObjectsParts::ObjectsParts(ViewerState& s) : session(s.session), views(s.views), selection(s.selection) {}

StatsParts::StatsParts(const ViewerState& s) : session(s.session), views(s.views), stats(s.stats) {}

ErrorParts::ErrorParts(ViewerState& s) : error(s.error), layout(s.layout) {}

StatusParts::StatusParts(const ViewerState& s)
    : error(s.error), status(s.status), layout(s.layout), item_positions(s.item_positions), cursor(s.cursor) {}

HelpParts::HelpParts(ViewerState& s) : show_help(s.show_help), layout(s.layout), item_positions(s.item_positions) {}

CreateParts::CreateParts(ViewerState& s) : EditContext(s), fields(s.fields) {}

MaterialParts::MaterialParts(ViewerState& s) : EditContext(s), fields(s.fields), display(s.display) {}

EditParts::EditParts(ViewerState& s)
    : EditContext(s),
      fields(s.fields),
      adaptive_tolerance(s.adaptive_tolerance),
      snap(s.snap),
      snap_size(s.snap_size),
      curve_editing(s.curve_editing) {}

PointTableParts::PointTableParts(ViewerState& s)
    : EditContext(s), split_t(s.fields.split_t), snap(s.snap), snap_size(s.snap_size) {}

PointTableParts::PointTableParts(const EditParts& p)
    : EditContext(p), split_t(p.fields.split_t), snap(p.snap), snap_size(p.snap_size) {}

CurveToolParts::CurveToolParts(ViewerState& s) : EditContext(s), editing(s.curve_editing) {}

CurveToolParts::CurveToolParts(const EditParts& p) : EditContext(p), editing(p.curve_editing) {}

}  // namespace sweep::viewer::panels
