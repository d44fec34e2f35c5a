"""The ensemble check of chaotic impacts (`python -m fsc ensemble`): its peaks, its statistics and
its verdict, a short run through the FMU in which the runs differ and the check can fail, and the
defaults' check for each worn joint against its converged ensemble.

The converged ensembles (rtol 1e-7) are the model's own answer, whatever the integrator's settings, and
take ten times a tested ensemble's time: they are recorded in `data/ensemble_<joint>.json` with the
model's parameters they were run at. A test fails until they are recorded afresh (`UPDATE_ENSEMBLES=1
pytest packaging/python/tests/test_ensemble.py`) if its parameters differ from the recorded ones, or if
the model's first impact (not chaotic) moved: the first run is run again and its first impact held to
the recorded one's within 1e-6."""
import json
import os
from pathlib import Path

import numpy as np
import pytest

from fsc import ensemble

#: Where the converged ensembles are recorded.
RECORDED = Path(__file__).resolve().parent / "data"


def test_peaks_are_the_local_maxima_after_the_first_contact():
    """The first impact is the first local maximum from the interval before the first onset on;
    later local maxima count above 10 % of it; a plateau's first sample is its maximum."""
    force = [0, 5, 0, 0, 100, 60, 80, 9, 20, 20, 0, 11, 0]
    onsets = [0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3]
    first, later = ensemble.peaks(force, onsets)
    assert first == 100
    assert later == [80, 20, 11]
    assert ensemble.peaks(force, [0] * len(force)) == (None, [])


def test_compare_judges_the_upper_quantiles_and_the_first_impacts():
    """Within the bound where the upper decile's mean, each run's largest and every first impact
    (against its converged twin's) are; the pooled largest, the 90th percentile, the median and the
    counts are reported, never judged; ensembles of different sizes are not compared."""
    rng = np.random.default_rng(1)
    reference = [(100.0 + k, list(rng.uniform(10, 90, 200)), 1000) for k in range(5)]

    def lower_half_lowered(peaks):
        thinned = np.sort(peaks)[::2]
        return list(np.where(thinned <= np.median(thinned), 0.8 * thinned, thinned))
    fewer = [(1.005 * r[0], lower_half_lowered(r[1]), 200) for r in reference]
    rows, ok = ensemble.compare(fewer, reference, 0.02)
    judged = [within for *_, is_judged, within in rows if is_judged]
    informative = {name: d for name, _, _, d, _, is_judged, _ in rows if not is_judged}
    assert ok and len(judged) == 3
    noise = [sigma for _, _, _, _, sigma, _, _ in rows if sigma is not None]
    assert len(noise) == 5 and all(0 <= sigma < 0.05 for sigma in noise) and noise[0] > 0
    assert informative["later peaks, median"] < -0.1
    assert informative["later peaks per run"] == -0.5
    shifted = [(r[0], [0.95 * p for p in r[1]], r[2]) for r in reference]
    assert not ensemble.compare(shifted, reference, 0.02)[1]
    first_off = [(r[0] * (1.03 if k == 3 else 1.0), r[1], r[2]) for k, r in enumerate(reference)]
    rows, ok = ensemble.compare(first_off, reference, 0.02)
    assert not ok and abs(rows[0][3] - 0.03) < 1e-12 and rows[0][2] == reference[3][0]
    one_high = [(r[0], r[1] + ([200.0] if k == 0 else []), r[2]) for k, r in enumerate(reference)]
    rows, ok = ensemble.compare(one_high, reference, 0.02)
    informative = {name: d for name, _, _, d, _, is_judged, _ in rows if not is_judged}
    assert not ok and informative["later peaks, largest"] > 1.2
    with pytest.raises(ValueError, match="as many runs"):
        ensemble.compare(reference[:4], reference, 0.02)


def test_an_ensembles_runs_differ_and_a_deliberate_error_fails(fmu, tmp_path):
    """Two-run ensembles over 6 ms at the defaults: the runs' later impacts differ while their first
    impacts agree to 1e-4 (the initial angles 1e-5 rad apart), the table and the picture are
    written, and a joint 20 % too stiff in the tested ensemble fails the check (exit status 1)."""
    from fmpy import extract, read_model_description
    md = read_model_description(fmu)
    runs = ensemble.ensemble(extract(fmu), md, {}, 1e-2, 2, "joint", 0.006, 1e-5, workers=1)
    assert all(first is not None and len(later) > 5 for first, later, _ in runs)
    assert runs[0][1] != runs[1][1]
    assert abs(runs[0][0] / runs[1][0] - 1) < 1e-4
    common = ["--runs", "2", "--stop", "0.006", "--reference-rtol", "1e-4", "--workers", "1",
              "--fmu", fmu]
    assert ensemble.main(common + ["--out", str(tmp_path / "same")]) in (0, 1)
    assert "later peaks, largest of each run" in (tmp_path / "same" / "ensemble.md").read_text()
    assert (tmp_path / "same" / "ensemble.png").stat().st_size > 10_000
    stiff = ensemble.main(common + ["--out", str(tmp_path / "stiff"), "--tested-only",
                                    "joint.youngsModulus=2.484e11"])
    assert stiff == 1


def converged(directory, md, start_values, runs, window):
    """The converged ensemble (rtol 1e-7) of `runs` runs over `window` with `start_values` as
    recorded (module docs), the recording's settings checked against the FMU's parameters."""
    physical = {v.name: v.start for v in md.modelVariables
                if v.causality == "parameter" and not v.name.startswith("solver.")}
    settings = {"start_values": start_values, "rtol": 1e-7, "runs": runs, "window": list(window),
                "perturbation": ensemble.PERTURBATION, "parameters": physical}
    path = RECORDED / f"ensemble_{window[0]}.json"
    if os.environ.get("UPDATE_ENSEMBLES"):
        computed = ensemble.ensemble(directory, md, start_values, 1e-7, runs, *window, workers=2)
        rounded = [[float(f"{first:.9g}"), [float(f"{p:.9g}") for p in later], steps]
                   for first, later, steps in computed]
        path.write_text(json.dumps({"settings": settings, "runs": rounded}) + "\n")
    recorded = json.loads(path.read_text())
    changed = {k: (recorded["settings"].get(k), settings.get(k))
               for k in recorded["settings"].keys() | settings.keys()
               if recorded["settings"].get(k) != settings.get(k)}
    assert not changed, f"{path.name} was recorded with other settings (recorded, now): {changed}"
    [(first, _, _)] = ensemble.ensemble(directory, md, start_values, 1e-7, 1, *window, workers=1)
    assert abs(first / recorded["runs"][0][0] - 1) < 1e-6, (
        f"{path.name}: the first impact is {first} N, recorded {recorded['runs'][0][0]} N")
    return [(first, later, steps) for first, later, steps in recorded["runs"]]


def check(fmu, joint, start_values, youngs_modulus):
    """Whether the 44-run ensemble at the FMU's default tolerance passes against the converged one
    (rtol 1e-7, recorded) over two revolutions, and whether it fails with the bearing's Young's
    modulus 20 % high (`youngs_modulus` names it): the two verdicts, with the rows of each
    comparison."""
    from fmpy import extract, read_model_description
    md = read_model_description(fmu)
    directory = extract(fmu)
    window = (joint, 0.024, 1e-5)
    runs = 44
    variables = {v.name: v for v in md.modelVariables}
    rtol = float(variables["solver.relativeTolerance"].start)
    reference = converged(directory, md, start_values, runs, window)
    tested = ensemble.ensemble(directory, md, start_values, rtol, runs, *window, workers=2)
    modulus = float(variables[youngs_modulus].start)
    stiff = ensemble.ensemble(directory, md, {**start_values, youngs_modulus: 1.2 * modulus},
                              rtol, runs, *window, workers=2)
    return ensemble.compare(tested, reference, 0.02), ensemble.compare(stiff, reference, 0.02)


def test_the_default_experiments_impacts_pass_at_the_defaults(fmu):
    """The rod–slider joint worn (the DefaultExperiment): at the default tolerance its ensemble
    passes against the converged one, and fails with the joint's Young's modulus 20 % high."""
    (rows, ok), (stiff_rows, stiff_ok) = check(fmu, "joint", {}, "joint.youngsModulus")
    assert ok, rows
    assert not stiff_ok, stiff_rows


def test_a_worn_main_bearing_passes_at_the_defaults(fmu):
    """A worn main bearing at the defaults (the FMU integrates a dry main bearing at rtol 1e-3 at
    most): its ensemble passes against the converged one, and fails with the bearing's Young's
    modulus 20 % high."""
    worn = {"mainBearing.model": 2, "joint.model": 1}
    (rows, ok), (stiff_rows, stiff_ok) = check(fmu, "mainBearing", worn, "mainBearing.youngsModulus")
    assert ok, rows
    assert not stiff_ok, stiff_rows


def test_a_worn_crank_pin_passes_at_the_defaults(fmu):
    """A worn crank pin at the defaults: its ensemble passes against the converged one, and fails
    with the pin's Young's modulus 20 % high."""
    worn = {"crankPin.model": 2, "joint.model": 1}
    (rows, ok), (stiff_rows, stiff_ok) = check(fmu, "crankPin", worn, "crankPin.youngsModulus")
    assert ok, rows
    assert not stiff_ok, stiff_rows
