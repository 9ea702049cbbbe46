#pragma once
// 3MF output for 3D printing (issue 58), through lib3mf: one file of every printable surface,
// in millimetres, z up, the whole model standing on the plate as one object.
#include "model/print/print_model.hpp"

#include <filesystem>
#include <string>

namespace sweep::io {

/// Writes the 3MF file of `model`: unit millimetre, one mesh object named `name` holding every
/// part's shell (already placed and welded: print_model.hpp) with its triangles' indices moved
/// past the earlier parts' (one model on the plate, its parts where they belong: a slicer would
/// drop separate objects to the plate or leave them floating), one build item with the identity
/// transform, and per part a base material named after it in its colour, which its triangles
/// carry. Throws std::runtime_error naming the path when lib3mf cannot. Precondition: the model
/// has a part.
void save_3mf_file(const std::filesystem::path& path, const PrintModel& model, const std::string& name);

}  // namespace sweep::io
