"""Shared fixtures: the repository, the CLI binary the numbers are compared with, and the
tolerances (read from src/tolerances.rs, the one place they live)."""

from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path
from typing import Any, Callable, Dict, List

import pytest

REPO = Path(__file__).resolve().parents[2]

#: System II of [S] (presets/system-2.toml: model 4, p* = 0.005) as the keywords of
#: ``asperity.Scene``, written out by hand.
SYSTEM_2: Dict[str, Any] = dict(
    system_size_m=25.6e-6,
    rolloff_wavelength_m=12.8e-6,
    short_wavelength_m=0.1e-6,
    hurst=0.8,
    rms_gradient=1.0,
    contact_modulus_pa=25e6,
    surface_energy_j_m2=0.157,
    range_m=14.2e-9,
    pressure=0.005,
    model=4,
)


def tolerance(name: str) -> float:
    """The constant `name` of src/tolerances.rs."""
    text = (REPO / "src" / "tolerances.rs").read_text()
    m = re.search(rf"pub const {name}: f64 = ([^;]+);", text)
    assert m, f"{name} not in src/tolerances.rs"
    return float(m.group(1).replace("_", ""))


def _binary() -> Path | None:
    env = os.environ.get("ASPERITY_BIN")
    if env:
        return Path(env)
    for profile in ("debug", "release"):
        p = REPO / "target" / profile / "asperity"
        if p.is_file():
            return p
    return None


@pytest.fixture(scope="session")
def cli() -> Callable[..., Dict[str, Any]]:
    """Runs the `asperity` binary (ASPERITY_BIN, else target/debug or target/release) with
    the arguments and parses its JSON; skips where no binary is built."""
    exe = _binary()
    if exe is None:
        if os.environ.get("ASPERITY_REQUIRE_CLI"):
            pytest.fail("no asperity binary (target/debug/asperity or ASPERITY_BIN) though ASPERITY_REQUIRE_CLI is set")
        pytest.skip("no asperity binary (cargo build or ASPERITY_BIN)")

    def run(*args: str) -> Dict[str, Any]:
        out = subprocess.run([str(exe), *args], check=True, capture_output=True, text=True, cwd=REPO)
        d: Dict[str, Any] = json.loads(out.stdout)
        return d

    return run


TIMING_KEYS = re.compile(r"(^|_)elapsed(_|$)")


def compare(py: Any, cli: Any, rel: float, path: str = "") -> List[str]:
    """Differences between two JSON values key by key (timings skipped): numbers to `rel`."""
    diffs: List[str] = []
    if isinstance(cli, dict):
        if not isinstance(py, dict):
            return [f"{path}: python {type(py).__name__}, cli object"]
        for k in cli:
            if TIMING_KEYS.search(k):
                continue
            if k not in py:
                diffs.append(f"{path}.{k}: missing in python")
                continue
            diffs += compare(py[k], cli[k], rel, f"{path}.{k}")
    elif isinstance(cli, list):
        if not isinstance(py, list) or len(py) != len(cli):
            return [f"{path}: lengths differ"]
        for i, (a, b) in enumerate(zip(py, cli)):
            diffs += compare(a, b, rel, f"{path}[{i}]")
    elif isinstance(cli, float) or (isinstance(cli, int) and not isinstance(cli, bool) and isinstance(py, float)):
        if not (isinstance(py, (int, float)) and abs(py - cli) <= rel * max(abs(py), abs(cli))):
            diffs.append(f"{path}: python {py!r}, cli {cli!r}")
    elif py != cli:
        diffs.append(f"{path}: python {py!r}, cli {cli!r}")
    return diffs
