#pragma once
// Sweep's public C++ API: spline curves and swept surfaces from SWP files. Link Sweep::sweep
// (CMake: find_package(Sweep)) or `pkg-config --cflags --libs sweep`. docs/library.md has the
// tour; each header documents what it declares.
//
//   #include <sweep/sweep.hpp>
//   sweep::Document doc = sweep::Document::load("wineglass.swp");   // throws sweep::Error
//   for (const sweep::SurfaceMesh& m : doc.surfaces())
//     std::printf("%s %zu\n", m.name.c_str(), m.positions.size() / 3);
#include <sweep/document.hpp>
#include <sweep/error.hpp>
#include <sweep/geometry.hpp>
#include <sweep/image.hpp>
#include <sweep/snapshot.hpp>
#include <sweep/version.hpp>
