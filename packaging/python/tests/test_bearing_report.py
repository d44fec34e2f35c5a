"""The bearing report on the compressor of `studies/compressor.toml` through fmpy: its cycle results
are what the communication-interval holds give over the last complete cycle, its files are written
for the clearance joints, and a wrong machine file is refused naming the entry."""
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
    machine, data = compressor
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
    assert "lubricated, finite film, isoviscous, smooth" in text
    assert f"cycle {int(data['cycle.number'])}." in text
    assert "FMU warnings: 0" in text


def test_the_report_draws_a_heated_rough_bearing(root, fmu, tmp_path):
    """A bearing with a heat balance and rough surfaces: its film temperature, viscosity and
    asperity load drawn, its hottest film tabulated in °C."""
    machine = report.load(root / "studies" / "compressor.toml", fmu=fmu, cycles=2)
    machine.parameters |= {"crankPin.thermalModel": 2, "crankPin.roughness": 1.5e-6}
    data = report.run(machine, progress=False)
    page = report.write(machine, data, tmp_path)
    text = page.read_text()
    assert "heat balance, roughness 1.5 µm" in text
    assert "crankPin.filmTemperatureMaxCycle" in text
    assert "crankPin.asperityForcePeakCycle" in text
    hottest = data["crankPin.filmTemperatureMaxCycle"] - 273.15
    assert 40.0 < hottest < 80.0
    assert (tmp_path / "crankPin.png").stat().st_size > 20_000


def test_a_wrong_machine_file_is_refused_naming_its_entry(tmp_path, fmu):
    bad = tmp_path / "bad.toml"
    bad.write_text('[parameters]\n"crankPin.filmModel" = "long"\n')
    with pytest.raises(StudyError, match="crankPin.filmModel = 'long' is not one of"):
        report.load(bad, fmu=fmu)
    bad.write_text('[parameters]\n"crankPin.model" = "lubricated"\n"crankPin.bearingLength" = 0.2\n')
    machine = report.load(bad, fmu=fmu)
    with pytest.raises(StudyError, match=r"crankPin.bearingLength = 0.2 .*finite film"):
        report.run(machine, progress=False)
