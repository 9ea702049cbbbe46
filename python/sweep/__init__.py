"""Sweep: spline curves and swept surfaces from SWP files.

    import sweep
    doc = sweep.load("wineglass.swp")          # raises sweep.SwpError with .line and .column
    m = doc.surfaces()[0]                      # m.positions (N, 3) float32, m.indices (M, 3) uint32
    doc.set_point("profile", 6, (-1.06, 1.1))  # an undoable edit, as the viewer's
    doc.save("wineglass.swp")                  # keeps the file's text: one line changes
    img = doc.render(640, 480)                 # (480, 640, 4) uint8, headless

Arrays are read-only views of the document's memory, not copies; each keeps that memory alive.
A Document shows itself in Jupyter (_repr_png_). pytest: `pytest_plugins = ["sweep.pytest_plugin"]`
gives the `sweep_snapshot` fixture (docs/python.md).
"""
from ._sweep import (  # noqa: F401
    Curve,
    Document,
    ObjectInfo,
    SnapshotResult,
    Surface,
    SwpError,
    __version__,
    check_snapshot,
    compare_images,
    load,
    parse,
    save_png,
)

__all__ = [
    "Curve",
    "Document",
    "ObjectInfo",
    "SnapshotResult",
    "Surface",
    "SwpError",
    "__version__",
    "check_snapshot",
    "compare_images",
    "load",
    "parse",
    "save_png",
]
