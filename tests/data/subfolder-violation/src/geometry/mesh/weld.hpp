#pragma once
// Breaks a rule of cmake/subfolders.cmake on purpose: mesh/ is the ground floor.
#include "geometry/curves/curve.hpp"
