#pragma once
// Writing a Document back to SWP text that the original format reads.
#include "model/document.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sweep::io {

/// SWP text for a document; numbers are written in shortest round-trip form, so
/// parse_swp(write_swp(doc)) == doc. If `first_lines` is given it receives the 1-based line on
/// which each object starts.
std::string write_swp(const Document& doc, std::vector<int>* first_lines = nullptr);

/// The lines write_swp writes for one object of `doc` (each ending in '\n', no blank line after).
std::string object_text(const Document& doc, const Object& object);

/// SWP text for a document read from a file, format-preserving: every token an edit did not
/// change keeps its text from doc.source, and so do the spaces, blank lines and line ends (CRLF
/// stays CRLF) around it and the order of the objects. A changed number is written with the
/// decimals its line used in the file (six in the starter files), more if that would move it
/// by more than a millionth of the scene's size (document_extent), the shortest exact text if
/// even 17 would; an integer as written. A new object is written as write_swp writes it,
/// after the blank lines the file puts between objects, with the file's line ends. Reading the
/// result gives the document (numbers to that millionth). Precondition: doc.source.text is set
/// and every object's location.begin..end is its span in it, or empty (made in memory).
std::string write_swp_preserving(const Document& doc);

/// SWP text for a new document, made in the editor rather than read from a file: write_swp's,
/// with the numbers of its points as write_swp_preserving writes a new object's points in a file
/// whose points have no decimals: the shortest text within a millionth of the scene's size
/// (document_extent), the precision a new document gets (so a point placed with the mouse is
/// -1.015506 in a scene about 4 across, not -1.0155057200058235). Other numbers (STEPS, radii,
/// clauses) are write_swp's. Reading the result gives the document, points to that millionth;
/// should it not, the result is write_swp's text.
std::string write_swp_rounded(const Document& doc);

/// How save_swp_file writes a document that was not read from a file (no doc.source).
enum class NewDocumentNumbers {
  Exact,    // write_swp: every number reads back as the same double (`sweep import`)
  Rounded,  // write_swp_rounded: points within a millionth of the scene's size (the editor)
};

/// Writes the document to `path` through a temporary file and a rename, so the old file
/// survives any failure: write_swp_preserving when it was read from a file (doc.source), else
/// write_swp or write_swp_rounded as `numbers` says. Throws std::runtime_error with a clear
/// message.
void save_swp_file(const std::filesystem::path& path, const Document& doc,
                   NewDocumentNumbers numbers = NewDocumentNumbers::Exact);

}  // namespace sweep::io
