"""`cmake --install` puts a package that imports and runs on its own: the compiled module, the
Python half and the type stubs, under ANTKIT_PYTHON_INSTALL_DIR below the prefix."""
import os
import subprocess
import sys
from pathlib import Path


def test_the_installed_package_imports_and_runs(tmp_path):
    build = os.environ["ANTKIT_BUILD_DIR"]
    subprocess.run(
        [os.environ.get("CMAKE_COMMAND", "cmake"), "--install", build, "--prefix", str(tmp_path),
         "--component", "python"],
        check=True, capture_output=True,
    )
    site = tmp_path / os.environ["ANTKIT_PYTHON_INSTALL_DIR"]
    files = {p.name for p in (site / "antkit").iterdir()}
    assert {"__init__.py", "__init__.pyi", "py.typed"} <= files
    assert any(f.startswith("_antkit") and f.endswith(".so") for f in files)
    code = (
        "import antkit, numpy as np\n"
        "m = antkit.Map.from_array(np.ones((4, 6), dtype=bool))\n"
        "r = antkit.stc(m, 'ant', start=(0, 0))\n"
        "c = antkit.check_stc(m, r.path, start=(0, 0))\n"
        "print(antkit.__file__, r.covered, c.ok)\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True,
                         env=env, cwd=tmp_path).stdout.split()
    assert Path(out[0]).is_relative_to(site)
    assert out[1:] == ["24", "True"]
