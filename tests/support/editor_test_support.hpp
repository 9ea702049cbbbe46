#pragma once
// What the editor tests share.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"

#include <string>

namespace sweep::editor::test {

/// A session on the document `text` (SWP), as if loaded from "test.swp".
inline EditSession session_of(const std::string& text) {
  EditSession session;
  session.load(io::parse_swp(text), "test.swp");
  return session;
}

}  // namespace sweep::editor::test
