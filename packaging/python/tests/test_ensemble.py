"""The ensemble check of chaotic impacts (`python -m fsc ensemble`): its peaks, its statistics and
its verdict, and a short run through the FMU in which the runs differ and the check can fail."""
import numpy as np

from fsc import ensemble


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
    """Within the bound where the upper decile's mean, the largest and every first impact are;
    the 90th percentile, the median and the counts are reported, never judged."""
    rng = np.random.default_rng(1)
    reference = [(100.0, list(rng.uniform(10, 90, 200)), 1000) for _ in range(5)]

    def lower_half_lowered(peaks):
        thinned = np.sort(peaks)[::2]
        return list(np.where(thinned <= np.median(thinned), 0.8 * thinned, thinned))
    fewer = [(100.5, lower_half_lowered(r[1]), 200) for r in reference]
    rows, ok = ensemble.compare(fewer, reference, 0.02)
    judged = [within for *_, is_judged, within in rows if is_judged]
    informative = {name: d for name, _, _, d, _, is_judged, _ in rows if not is_judged}
    assert ok and len(judged) == 3
    noise = [sigma for _, _, _, _, sigma, _, _ in rows if sigma is not None]
    assert len(noise) == 4 and all(0 <= sigma < 0.05 for sigma in noise) and noise[0] > 0
    assert informative["later peaks, median"] < -0.1
    assert informative["later peaks per run"] == -0.5
    shifted = [(100.0, [0.95 * p for p in r[1]], r[2]) for r in reference]
    assert not ensemble.compare(shifted, reference, 0.02)[1]
    first_off = [(103.0, r[1], r[2]) for r in reference]
    assert not ensemble.compare(first_off, reference, 0.02)[1]


def test_an_ensembles_runs_differ_and_a_deliberate_error_fails(fmu, tmp_path):
    """Two-run ensembles over 6 ms at the defaults: the runs' impact sequences differ (the initial
    angle's 1e-12 rad reaches them), the table and the picture are written (with a second family
    of the tested ensemble, perturbed from k = 2 on), and a joint 20 % too stiff in the tested
    ensemble fails the check (exit status 1)."""
    from fmpy import extract, read_model_description
    md = read_model_description(fmu)
    runs = ensemble.ensemble(extract(fmu), md, {}, 1e-2, 2, "joint", 0.006, 1e-5, workers=1)
    assert all(first is not None and len(later) > 5 for first, later, _ in runs)
    assert runs[0][1] != runs[1][1]
    assert abs(runs[0][0] / runs[1][0] - 1) < 1e-6
    common = ["--runs", "2", "--stop", "0.006", "--reference-rtol", "1e-4", "--workers", "1",
              "--fmu", fmu]
    assert ensemble.main(common + ["--out", str(tmp_path / "same"), "--families", "2"]) in (0, 1)
    text = (tmp_path / "same" / "ensemble.md").read_text()
    assert "Further families" in text and "| 2 … |" in text
    assert (tmp_path / "same" / "ensemble.png").stat().st_size > 10_000
    stiff = ensemble.main(common + ["--out", str(tmp_path / "stiff"), "--tested-only",
                                    "joint.youngsModulus=2.484e11"])
    assert stiff == 1


def test_a_worn_main_bearing_passes_at_the_advised_tolerance(fmu):
    """The limits advise rtol 1e-3 for a worn main bearing's load spectrum: over two revolutions
    its 44-run ensemble there passes against the converged one (rtol 1e-7), and the same ensemble
    with the bearing's Young's modulus 20 % high fails."""
    from fmpy import extract, read_model_description
    md = read_model_description(fmu)
    directory = extract(fmu)
    worn = {"mainBearing.model": 2, "joint.model": 1}
    window = ("mainBearing", 0.024, 1e-5)
    reference = ensemble.ensemble(directory, md, worn, 1e-7, ensemble.RUNS, *window, workers=2)
    advised = ensemble.ensemble(directory, md, worn, 1e-3, ensemble.RUNS, *window, workers=2)
    rows, ok = ensemble.compare(advised, reference, 0.02)
    assert ok, rows
    modulus = next(float(v.start) for v in md.modelVariables
                   if v.name == "mainBearing.youngsModulus")
    stiff = ensemble.ensemble(directory, md, {**worn, "mainBearing.youngsModulus": 1.2 * modulus},
                              1e-3, ensemble.RUNS, *window, workers=2)
    rows, ok = ensemble.compare(stiff, reference, 0.02)
    assert not ok, rows
