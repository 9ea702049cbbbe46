#pragma once
// A small file with riders, shared by the viewer's timeline tests (with and without a window).

namespace sweep::test {

/// Two riders a half loop apart on a trefoil knot, the second upright about +y.
inline constexpr const char* kTwoRidersOnAKnot =
    "knot track 200 2 3 2 0.6\n"
    "circ body 16 0.15\n"
    "poly3 spine 2\n[0 0 -0.4]\n[0 0 0.4]\n"
    "gcyl plane body spine caps\n"
    "rider r1 track plane seconds 6\n"
    "rider r2 track plane seconds 6 start 0.5 up 0 1 0\n";

}  // namespace sweep::test
