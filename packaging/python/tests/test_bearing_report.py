"""The bearing report on the compressor of `studies/compressor.toml` through fmpy: its cycle results
are what the communication-interval holds give over the last complete cycle, the one it draws,
wherever the run starts; its files are written for the clearance joints, its operating limits
checked against their sources' values; and a wrong machine file is refused naming the entry."""
import math

import numpy as np
import pytest

from fsc import bearing_report as report
from fsc.study import StudyError


@pytest.fixture(scope="module")
def compressor(root, fmu):
    machine = report.load(root / "studies" / "compressor.toml", fmu=fmu)
    return machine, report.run(machine, progress=False)


def test_the_cycle_results_are_the_interval_holds_over_the_last_cycle(compressor):
    """Over the last complete cycle of the compressor's lubricated main bearing and crank pin and its
    dry piston pin: the smallest film thickness, the largest film pressure and force equal the
    extremes of the communication intervals' holds within 0.5 %, at crank angles within 1° (the
    holds locate an extreme within the half-degree interval that holds it); the mean friction power
    and oil flow equal the trapezoidal means of the outputs at the communication points within
    0.5 %. Measured: the extremes equal, their angles within 0.9° (a step's inner extreme is held
    by the interval its step ends in), the means within 0.45 % (the dry pin's friction, spiky at its
    impacts) and 0.15 % (the films)."""
    _, data = compressor
    assert_cycle_results_are_the_drawn_cycle(data)


def assert_cycle_results_are_the_drawn_cycle(data):
    """The cycle results equal the holds' extremes and the trapezoidal means over the rows the
    report draws (the tolerances above)."""
    rows = report.last_cycle(data)
    angle = np.degrees(np.mod(data["crank.angle"][rows], data["period"]))
    time = data["time"][rows]
    for prefix, *_ in report.JOINTS:
        if data[f"{prefix}.model"] == 1:
            continue
        holds = [("filmThicknessMin", np.argmin, "filmThicknessMinCycle"),
                 ("filmPressurePeak", np.argmax, "filmPressurePeakCycle"),
                 ("forcePeak", np.argmax, "forcePeakCycle")]
        for series, extreme, cycle in holds:
            values = data[f"{prefix}.{series}"][rows]
            k = extreme(values)
            expected = data[f"{prefix}.{cycle}"]
            scale = max(abs(expected), 1e-9 * data[f"{prefix}.clearance"])
            assert abs(values[k] - expected) <= 5e-3 * scale, (prefix, series, values[k], expected)
            if values[k] > 0:
                gap = abs(angle[k] - data[f"{prefix}.{cycle}Angle"])
                assert min(gap, 360 - gap) <= 1.0, (prefix, series, angle[k],
                                                    data[f"{prefix}.{cycle}Angle"])
        for series, cycle in [("frictionPower", "frictionPowerMeanCycle"),
                              ("oilFlow", "oilFlowMeanCycle")]:
            values = data[f"{prefix}.{series}"][rows]
            mean = np.trapezoid(values, time) / (time[-1] - time[0])
            expected = data[f"{prefix}.{cycle}"]
            assert abs(mean - expected) <= 5e-3 * max(abs(expected), 1e-12), (prefix, series, mean,
                                                                                expected)


def test_the_report_draws_each_clearance_joint(compressor, tmp_path):
    """index.html with the cycle results of the two lubricated bearings and the piston pin (its
    force and friction, no film), each joint's models named, the cycle drawn numbered, and one PNG
    per clearance joint."""
    machine, data = compressor
    page = report.write(machine, data, tmp_path)
    text = page.read_text()
    for prefix in ["mainBearing", "crankPin", "joint"]:
        assert (tmp_path / f"{prefix}.png").stat().st_size > 10_000
        assert f"{prefix}.forcePeakCycle" in text
    for prefix in ["mainBearing", "crankPin"]:
        assert f"{prefix}.filmThicknessMinCycle" in text
    assert "joint.filmThicknessMinCycle" not in text
    assert "lubricated, finite film, isoviscous, smooth, unfed" in text
    assert f"cycle {int(data['cycle.number'])}." in text
    assert "FMU warnings: 0" in text
    # The operating limits: the crank pin (24 mm at 1.9 m/s) and the main bearing (30 mm at
    # 2.4 m/s) against ISO 7902-3's 4 µm, every joint's specific load against 25 MPa.
    assert text.count("<h3>Operating limits</h3>") == 3
    assert text.count("largest specific load") == 3
    assert text.count("smallest film h_min") == 2
    assert "(24 mm, 1.8" in text or "(24 mm, 1.9" in text
    assert "(30 mm, 2.3" in text or "(30 mm, 2.4" in text
    assert text.count("<td>4 µm</td>") == 2
    assert "beyond" not in text


def test_the_film_limit_is_the_standards_table():
    """ISO 7902-3's h_lim at its rows' and columns' bounds and beyond them."""
    assert report.film_limit(0.024, 0.5) == 3e-6
    assert report.film_limit(0.063, 1.0) == 3e-6
    assert report.film_limit(0.0631, 1.01) == 5e-6
    assert report.film_limit(0.3, 12.0) == 11e-6
    assert report.film_limit(3.0, 40.0) == 18e-6
    assert report.film_limit(0.01, 40.0) == 10e-6


def test_the_report_draws_a_heated_rough_fed_bearing(root, fmu, tmp_path):
    """A crank pin with a heat balance, rough surfaces and a feed hole in the journal, the run
    starting 0.5° past a cycle boundary (so that it ends 0.5° past one): its film temperature,
    viscosity, asperity load and the feed's flow drawn, its hottest film tabulated in °C, its
    models named, the limits of its film ratio and temperature checked — a limit of the machine
    file's named as its source — and the cycle results those of the cycle drawn."""
    machine = report.load(root / "studies" / "compressor.toml", fmu=fmu, cycles=2)
    machine.parameters |= {"crankPin.thermalModel": 2, "crankPin.roughness": 1.5e-6,
                           "crankPin.feed": 2, "crankPin.feedLocation": 2,
                           "crankPin.feedPosition": math.pi, "crank.initialAngle": 0.5 * math.pi
                           / 180.0}
    machine.limits["temperature"] = (323.15, "the machine file")
    data = report.run(machine, progress=False)
    assert abs(np.degrees(data["crank.angle"][-1]) % 360.0 - 0.5) < 0.5
    assert_cycle_results_are_the_drawn_cycle(data)
    # the first whole cycle is the second period, the one drawn (the first only begins at 0.5°)
    assert int(data["cycle.number"]) == 1
    page = report.write(machine, data, tmp_path)
    text = page.read_text()
    assert "heat balance, roughness 1.5 µm, feed hole 4 mm in the journal at 180°" in text
    assert "crankPin.filmTemperatureMaxCycle" in text
    assert "crankPin.asperityForcePeakCycle" in text
    hottest = data["crankPin.filmTemperatureMaxCycle"] - 273.15
    assert 40.0 < hottest < 80.0
    rows = report.last_cycle(data)
    feed = data["crankPin.feedFlow"][rows]
    assert np.all(feed > 0) and np.all(feed < data["crankPin.oilFlow"][rows])
    assert "smallest film ratio h_min/σ" in text
    verdict = "within" if hottest < 50.0 else "<b>beyond</b>"
    assert f"<td>50 °C</td><td>{verdict}</td><td>the machine file</td>" in text
    assert (tmp_path / "crankPin.png").stat().st_size > 20_000


def test_a_wrong_machine_file_is_refused_naming_its_entry(tmp_path, fmu):
    bad = tmp_path / "bad.toml"
    bad.write_text('[limits]\nfilm = 3e-6\n')
    with pytest.raises(StudyError, match="limits. film is not one of specific_load"):
        report.load(bad, fmu=fmu)
    bad.write_text('[limits]\ntemperature = -3\n')
    with pytest.raises(StudyError, match="temperature = -3 is not a positive number"):
        report.load(bad, fmu=fmu)
    bad.write_text('[parameters]\n"crankPin.filmModel" = "long"\n')
    with pytest.raises(StudyError, match="crankPin.filmModel = 'long' is not one of"):
        report.load(bad, fmu=fmu)
    bad.write_text('[parameters]\n"crankPin.model" = "lubricated"\n"crankPin.bearingLength" = 0.2\n')
    machine = report.load(bad, fmu=fmu)
    with pytest.raises(StudyError, match=r"crankPin.bearingLength = 0.2 .*finite film"):
        report.run(machine, progress=False)
