#!/usr/bin/env python3
"""Sweep from Python against scipy (issue 57): one cubic B-spline curve evaluated at 1,000,000
parameters, side by side with scipy.interpolate.BSpline on the same control points (uniform knots,
the curve a bsp2 is), and a mesh's arrays reaching Python for a small and a 100x larger surface
(constant time: no copy). Prints the medians of 7 runs and the ratios the README quotes.

Usage: PYTHONPATH=build/python /usr/bin/python3 benchmarks/python/curve_speed.py"""
import statistics
import time

import numpy as np
from scipy.interpolate import BSpline

import sweep

POINTS = np.array([[0, 0], [1, 2], [2, -1], [3, 3], [4, 0], [5, 2], [6, -2], [7, 1], [8, 0], [9, 3]], float)
COUNT = 1_000_000
RUNS = 7


def median_ms(work):
    times = []
    for _ in range(RUNS):
        start = time.perf_counter()
        work()
        times.append((time.perf_counter() - start) * 1000.0)
    return statistics.median(times)


def curve_document():
    points = " ".join(f"[{x:g} {y:g}]" for x, y in POINTS)
    return sweep.parse(f"bsp2 c 10 {len(POINTS)}\n{points}\n", "speed.swp")


def scipy_curve():
    degree = 3
    knots = np.arange(-degree, len(POINTS) + 1, dtype=float)  # uniform: piece i spans [i, i + 1]
    return BSpline(knots, POINTS, degree), len(POINTS) - degree


def main():
    doc = curve_document()
    low, high = doc.curve_range("c")
    t = np.linspace(low, high, COUNT)
    spline, pieces = scipy_curve()
    assert high == pieces
    np.testing.assert_allclose(doc.curve_points("c", t)[:, :2], spline(t), atol=1e-9)  # the same curve

    scipy_ms = median_ms(lambda: spline(t))
    points_ms = median_ms(lambda: doc.curve_points("c", t))
    frames_ms = median_ms(lambda: doc.evaluate_curve("c", t))
    print(f"{COUNT:,} parameters, cubic B-spline of {len(POINTS)} points (median of {RUNS}):")
    print(f"  scipy.interpolate.BSpline (positions):   {scipy_ms:7.1f} ms")
    print(f"  sweep curve_points (positions):           {points_ms:7.1f} ms  ({scipy_ms / points_ms:.2f}x scipy)")
    print(f"  sweep evaluate_curve (positions, frames): {frames_ms:7.1f} ms  ({scipy_ms / frames_ms:.2f}x scipy)")

    small = sweep.parse(f"bsp2 p 4 4\n[0 0] [1 1] [1 2] [0 3]\nsrev s 8 p\n", "small.swp")
    large = sweep.parse(f"bsp2 p 400 4\n[0 0] [1 1] [1 2] [0 3]\nsrev s 800 p\n", "large.swp")
    for name, doc in (("small", small), ("large", large)):
        surface = doc.surface("s")
        us = median_ms(lambda: (surface.positions, surface.normals, surface.indices)) * 1000.0
        print(f"  mesh arrays of a {name} surface ({surface.vertex_count:,} vertices): {us:6.1f} us")


if __name__ == "__main__":
    main()
