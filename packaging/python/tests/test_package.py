"""The package works installed from its wheel, away from the repository: built with pip, installed
(not editable) into a fresh environment, its `fsc` command runs a study from another directory
given the FMU's path."""
import subprocess
import sys
import sysconfig
from pathlib import Path

from conftest import ROOT


def test_an_installed_wheel_runs_a_study_from_elsewhere(tmp_path, fmu):
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check", "-q"]
    subprocess.run([*pip, "wheel", "--no-deps", "-w", str(tmp_path / "wheels"),
                    str(ROOT / "packaging" / "python")], check=True, timeout=600)
    (wheel,) = (tmp_path / "wheels").glob("fsc-*.whl")
    env = tmp_path / "env"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(env)], check=True)
    python = env / "bin" / "python"
    subprocess.run([*pip, "--python", str(python), "install", "--no-deps", str(wheel)],
                   check=True, timeout=600)
    # The dependencies from this environment (a path, not its editable install of the package).
    site = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                          capture_output=True, text=True, check=True).stdout.strip()
    Path(site, "dependencies.pth").write_text(sysconfig.get_path("purelib") + "\n")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "tiny.toml").write_text(
        'fmu = "FlexibleSliderCrank.fmu"\nstop_time = 0.002\noutput_interval = 1e-4\n\n'
        '[grid]\n"joint.clearance" = [1e-4, 5e-4]\n')
    where = subprocess.run([str(python), "-c", "import fsc; print(fsc.__file__)"], cwd=elsewhere,
                           capture_output=True, text=True, check=True).stdout
    assert where.startswith(site), where
    run = subprocess.run([str(env / "bin" / "fsc"), "sweep", "tiny.toml", "--fmu", fmu,
                          "--workers", "1"], cwd=elsewhere, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    assert "2 cases, 2 run now" in run.stdout
    assert (elsewhere / "target" / "studies" / "tiny" / "summary.txt").exists()
