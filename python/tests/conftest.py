"""Shared fixtures: the command-line programs the package is compared with."""

from __future__ import annotations

import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def bin_dir() -> pathlib.Path:
    """The directory of the `wedge` and `impact` programs: $DYNCONTACT_BIN_DIR, or the
    repository's release build (built here when absent)."""
    d = pathlib.Path(os.environ.get("DYNCONTACT_BIN_DIR", REPO / "target" / "release"))
    if not ((d / "wedge").exists() and (d / "impact").exists()):
        subprocess.run(
            ["cargo", "build", "--release", "--bin", "wedge", "--bin", "impact"],
            cwd=REPO,
            check=True,
        )
    return d


@pytest.fixture(scope="session")
def cli(bin_dir):
    """Runs a program with arguments and returns its stdout (it must succeed)."""

    def run(program: str, *args: str) -> str:
        p = subprocess.run(
            [str(bin_dir / program), *args], capture_output=True, text=True, check=False
        )
        assert p.returncode == 0, p.stderr
        return p.stdout

    return run
