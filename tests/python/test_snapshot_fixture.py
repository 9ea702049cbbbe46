"""The sweep_snapshot fixture, used as a project's tests would use it (pytester runs them): the
first run writes the reference and fails, the second passes, a moved control point fails and
names the object that changed, --sweep-update accepts it."""
import shutil

from conftest import SWP

USER_TEST = """
import sweep

def test_glass(sweep_snapshot):
    sweep_snapshot(sweep.load("wineglass.swp"))
"""


def test_the_snapshot_fixture_names_the_object_that_changed(pytester):
    shutil.copy(SWP / "wineglass.swp", pytester.path / "wineglass.swp")
    pytester.makeconftest('pytest_plugins = ["sweep.pytest_plugin"]')
    pytester.makepyfile(test_user=USER_TEST)

    first = pytester.runpytest()
    first.assert_outcomes(failed=1)
    first.stdout.fnmatch_lines(["*new test_glass-smooth: new reference*", "*pytest --sweep-update*"])
    assert (pytester.path / "__snapshots__" / "test_glass-smooth.png").exists()

    pytester.runpytest().assert_outcomes(passed=1)

    glass = pytester.path / "wineglass.swp"
    glass.write_text(glass.read_text().replace("[-1.164785 1.105511]", "[-1.214785 1.105511]"))
    moved = pytester.runpytest()
    moved.assert_outcomes(failed=1)
    moved.stdout.fnmatch_lines(["*FAIL test_glass-smooth: *pixels changed where the model changed*",
                                "*wineglass: *its mesh moved up to 0.03*"])

    pytester.runpytest("--sweep-update").assert_outcomes(passed=1)
    pytester.runpytest().assert_outcomes(passed=1)
