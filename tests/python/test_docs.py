"""docs/python.md runs as written: its Python blocks in order in one namespace (in a folder
holding wineglass.swp), the blocks that start with `# file: NAME` written as files, and those
files run by pytest as the page says (the first run writes the references and fails, the second
passes)."""
import os
import re
import shutil
from pathlib import Path

from conftest import SWP

DOC = Path(__file__).resolve().parents[2] / "docs" / "python.md"


def python_blocks():
    return re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S)


def test_every_python_block_of_the_guide_runs(tmp_path, pytester):
    shutil.copy(SWP / "wineglass.swp", tmp_path / "wineglass.swp")
    files = {}
    namespace = {}
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        for block in python_blocks():
            first = block.splitlines()[0]
            if first.startswith("# file: "):
                files[first[len("# file: "):]] = block
            else:
                exec(compile(block, str(DOC), "exec"), namespace)
    finally:
        os.chdir(here)
    assert (tmp_path / "wineglass.png").exists() and (tmp_path / "out_wineglass.glb").exists()
    edited = (tmp_path / "wineglass-edited.swp").read_text().splitlines()
    original = (tmp_path / "wineglass.swp").read_text().splitlines()
    assert sum(a != b for a, b in zip(edited, original)) == 1

    assert set(files) == {"conftest.py", "test_glass.py"}
    shutil.copy(SWP / "wineglass.swp", pytester.path / "wineglass.swp")
    for name, text in files.items():
        (pytester.path / name).write_text(text)
    pytester.runpytest().assert_outcomes(failed=2)
    pytester.runpytest().assert_outcomes(passed=2)
