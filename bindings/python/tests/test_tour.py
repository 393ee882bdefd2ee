"""The tutorial script (examples/tour.py) runs on the shipped sample and every stage stays valid."""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOUR = os.path.join(HERE, "..", "examples", "tour.py")
SPOT = os.path.join(HERE, "..", "..", "..", "data", "spot_control_mesh.obj")


def test_the_tour_runs_every_stage_and_draws_it(tmp_path):
    out = subprocess.run(
        [sys.executable, TOUR, SPOT, "--out", str(tmp_path)], capture_output=True, text=True, timeout=300
    )
    assert out.returncode == 0, out.stderr
    stages = ["loaded", "edited", "subdivided", "decimated", "broken"]
    for name in stages:
        line = next(l for l in out.stdout.splitlines() if l.startswith(name))
        assert line.split()[-1] == "valid", line
        png = tmp_path / f"python_tour_{name}.png"
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "refused, nothing changed" in out.stdout
    assert "shards" in out.stdout
