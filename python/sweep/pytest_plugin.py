"""pytest plugin: the `sweep_snapshot` fixture, screenshot regression of documents inside tests.

Enable it in a conftest.py with `pytest_plugins = ["sweep.pytest_plugin"]` (or `pytest -p
sweep.pytest_plugin`). A test calls `sweep_snapshot(doc)`: the document's picture is compared with
`__snapshots__/TEST-MODE.png` beside the test file, as `sweep snapshot` compares (the reference's
camera, anti-aliasing and one-pixel shifts forgiven, attribution to named objects). The first run
writes the reference and fails, as a new `sweep snapshot` case does; `pytest --sweep-update`
accepts new and changed pictures.
"""
from pathlib import Path

import pytest

from . import _sweep


def pytest_addoption(parser):
    parser.addoption(
        "--sweep-update",
        action="store_true",
        default=False,
        help="sweep_snapshot: write the references of new pictures and rewrite those that fail",
    )


class SnapshotFailure(AssertionError):
    """A picture that does not match its reference: the message names the objects that changed."""


@pytest.fixture
def sweep_snapshot(request):
    """Returns check(doc, name=None, mode="smooth", width=320, height=240, **limits).

    `name` defaults to the test's name; limits are `threshold` and `max_diff_pixels`. Raises
    SnapshotFailure with `sweep snapshot`'s message and one line per object that changed."""
    folder = Path(str(request.fspath)).parent / "__snapshots__"
    update = request.config.getoption("--sweep-update")

    def check(document, name=None, mode="smooth", width=320, height=240, **limits):
        case = name or request.node.name
        result = _sweep.check_snapshot(
            document, folder, case, mode=mode, width=width, height=height, update=update, **limits
        )
        if not result.passed:
            lines = [f"{result.status} {case}-{mode}: {result.message}"] + [
                "  " + line for line in result.objects
            ]
            if result.status == "new":
                lines.append("  (a new reference was written; run pytest --sweep-update to accept it)")
            raise SnapshotFailure("\n".join(lines))
        return result

    return check
