"""The tutorial script (examples/tour.py) runs on the shipped sample and every stage stays valid."""

import os
import subprocess
import sys

import hedge

HERE = os.path.dirname(os.path.abspath(__file__))
TOUR = os.path.join(HERE, "..", "examples", "tour.py")
SPOT = os.path.join(HERE, "..", "..", "..", "data", "spot_control_mesh.obj")


def run_python(args, **kwargs):
    """Runs a script with the hedge package this test imports (PYTHONPATH may be relative)."""
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(hedge.__file__)))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([package_root, os.environ.get("PYTHONPATH", "")]))
    return subprocess.run([sys.executable, *args], env=env, capture_output=True, text=True, timeout=300, **kwargs)


def test_the_tour_runs_every_stage_and_draws_it(tmp_path):
    out = run_python([TOUR, SPOT, "--out", str(tmp_path)])
    assert out.returncode == 0, out.stderr
    stages = ["loaded", "edited", "subdivided", "decimated", "broken"]
    for name in stages:
        line = next(l for l in out.stdout.splitlines() if l.startswith(name))
        assert line.split()[-1] == "valid", line
        png = tmp_path / f"python_tour_{name}.png"
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "refused, nothing changed" in out.stdout
    assert "shards" in out.stdout


def test_the_readme_tutorial_runs(tmp_path):
    # The README's tutorial block, run as written in a folder where data/ is the shipped samples.
    with open(os.path.join(HERE, "..", "README.md"), encoding="utf-8") as f:
        readme = f.read()
    start = readme.index("## Tutorial")
    block = readme[readme.index("```python\n", start) + len("```python\n") : readme.index("```\n", start + 20)]
    assert "hedge.read" in block and "fracture" in block and "render" in block
    os.symlink(os.path.abspath(os.path.join(HERE, "..", "..", "..", "data")), tmp_path / "data")
    script = tmp_path / "tutorial.py"
    script.write_text(block, encoding="utf-8")
    out = run_python([str(script)], cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "broken.png").read_bytes()[:4] == b"\x89PNG"
    assert "refused: " in out.stdout
