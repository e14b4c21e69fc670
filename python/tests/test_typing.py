"""The stubs agree with the package (mypy's stubtest), and type-check a user's script."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest


def test_stubtest_passes():
    pytest.importorskip("mypy")
    p = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "dyncontact"], capture_output=True, text=True
    )
    assert p.returncode == 0, p.stdout + p.stderr


def test_a_script_type_checks(tmp_path):
    pytest.importorskip("mypy")
    script = tmp_path / "use.py"
    script.write_text(textwrap.dedent("""
        import dyncontact
        r = dyncontact.wedge.solve(theta_deg=86, gamma=0.6, alpha=561.249)
        v: float = r.v_over_c1_cot_theta
        run = dyncontact.impact.run(profile="parabola:R=1", mass_ratio=10, v0_over_c1=0.01, end=1, poisson=0.3)
        keys: list[str] = run.history_keys()
        out = dyncontact.sweep(dyncontact.wedge.solve, dyncontact.cases(theta_deg=[80], alpha=[300]))
    """))
    bad = tmp_path / "bad.py"
    bad.write_text("import dyncontact\ndyncontact.wedge.solve(theta_deg=86, alpha=[1, 2])\n")
    ok = subprocess.run([sys.executable, "-m", "mypy", "--strict", str(script)], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stdout
    wrong = subprocess.run([sys.executable, "-m", "mypy", str(bad)], capture_output=True, text=True)
    assert wrong.returncode != 0 and "alpha" in wrong.stdout, wrong.stdout
