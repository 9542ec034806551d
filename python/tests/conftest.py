"""Shared fixtures of the Python tests: the antkit command (ANTKIT_CLI, set by ctest) to hold every
binding against, and the repository's maps (ANTKIT_MAPS_DIR)."""
import json
import os
import shutil
import subprocess
from pathlib import Path

import tempfile

import pytest
from hypothesis import HealthCheck, settings
from hypothesis.configuration import set_hypothesis_home_dir

# Hypothesis's own files (its Unicode tables) go to the build tree, not beside the sources.
set_hypothesis_home_dir(
    Path(os.environ["ANTKIT_BUILD_DIR"]) / "python" / ".hypothesis"
    if os.environ.get("ANTKIT_BUILD_DIR")
    else Path(tempfile.gettempdir()) / "antkit_hypothesis"
)

# Reproducible from the log: no example database (nothing carried between runs), derandomised
# unless ctest passes --hypothesis-seed (it does: ANTKIT_HYPOTHESIS_SEED, printed by pytest).
settings.register_profile(
    "antkit", database=None, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("antkit")

CLI = os.environ.get("ANTKIT_CLI", "")
SOURCE = Path(os.environ.get("ANTKIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
MAPS = Path(os.environ.get("ANTKIT_MAPS_DIR", Path(__file__).resolve().parents[2] / "data" / "maps"))


def cli(*args, status=0):
    """Runs `antkit ARGS --format json` and returns (exit status, parsed stdout or None, stderr)."""
    if not CLI:
        pytest.fail("ANTKIT_CLI is not set: run the tests through ctest (label python)")
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert r.returncode == status, f"antkit {' '.join(map(str, args))}: {r.returncode}\n{r.stderr}"
    out = json.loads(r.stdout) if r.stdout.strip() else None
    return out, r.stderr


@pytest.fixture(scope="session")
def maps_dir():
    assert MAPS.is_dir(), f"{MAPS}: no maps"
    return MAPS


def pytest_configure(config):
    # Without a seed (pytest run by hand) under CI, derandomised: the same examples every run.
    if config.getoption("hypothesis_seed", None) is None and os.environ.get("CI"):
        settings.register_profile("antkit-ci", settings.get_profile("antkit"), derandomize=True)
        settings.load_profile("antkit-ci")


def pytest_report_header(config):
    seed = config.getoption("hypothesis_seed", None)
    if seed is None:
        how = "derandomized (CI is set)" if os.environ.get("CI") else "random"
        return f"hypothesis seed: none given, {how}; ctest passes ANTKIT_HYPOTHESIS_SEED"
    return f"hypothesis seed: {seed} (ctest passes ANTKIT_HYPOTHESIS_SEED; rerun with --hypothesis-seed={seed})"


@pytest.fixture(scope="session")
def ros_bags(tmp_path_factory):
    """ROS 2 bags written by independent writers under node (tests/support/write_bags.mjs: what it
    writes and what the walks are). Skipped, saying so, only where node is absent; node present
    but its packages missing (`npm ci` not run) is a failure."""
    if shutil.which("node") is None:
        pytest.skip("node (Node.js 20) is not installed: no test bags are written")
    out = tmp_path_factory.mktemp("ros_bags")
    r = subprocess.run(["node", str(SOURCE / "tests/support/write_bags.mjs"), str(out)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, f"write_bags.mjs failed (run `npm ci` in the checkout):\n{r.stderr}"
    return out
