#pragma once
// Keeps the rules: surfaces/ may include curves/.
#include "geometry/curves/curve.hpp"
