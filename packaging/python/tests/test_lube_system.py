"""The lubrication-circuit FMU and the system it makes with the slider-crank (target/fmu/LubeCrank.ssp,
target/fmu/lube-crank/): the circuit's declared initial dependencies, and the system run by
libcosim (from the SSP and from the OSP system structure), by fmpy's master in FMI 2 and FMI 3, its
gallery pressure against the exact solution of its equation under the bearings' held draw."""
import math

import numpy as np
import pytest
from fmpy import read_model_description
from fmpy.validation import validate_fmu

from fsc import dependencies, lube_system
from fsc.session import Session

from conftest import ROOT

FMUS = ROOT / "target" / "fmu"
CIRCUIT_FMU = FMUS / lube_system.CIRCUIT
CRANK_FMU = FMUS / lube_system.CRANK
SSP = FMUS / "LubeCrank.ssp"
OSP = FMUS / "lube-crank" / "OspSystemStructure.xml"

STOP, STEP = 0.08, 1e-4
NS = 100_000  # STEP in libcosim's nanoseconds
PRESSURE = "lubricationCircuit.oil.supplyPressure"
FLOWS = ["sliderCrank.mainBearing.oilFlow", "sliderCrank.crankPin.oilFlow"]


@pytest.fixture(scope="module")
def fmpy_rows():
    return lube_system.run(STEP, STOP, outputs=("sliderCrank.oil.supplyPressure",))


def test_the_circuit_passes_fmpy_validation():
    assert validate_fmu(str(CIRCUIT_FMU)) == []


def test_circuit_declared_initial_dependencies_are_the_measured_ones():
    """ModelStructure/InitialUnknowns of the circuit: perturbing each input and parameter in
    initialization mode changes exactly the declared outputs, with the bearings drawing oil and
    heating it, and with a gallery they empty."""
    configurations = [{"crankPin.oilFlow": 1e-6, "crankPin.heatFlow": 10.0},
                      {"joint.oilFlow": 2e-6, "mainBearing.heatFlow": 5.0},
                      {"joint.oilFlow": 6e-6}]
    measured, n = dependencies.measure(str(CIRCUIT_FMU), configurations)
    assert n == len(configurations)
    assert measured == dependencies.declared(str(CIRCUIT_FMU))


def test_the_gallery_follows_its_equation_under_the_bearings_draw(fmpy_rows):
    """Over two revolutions of the compressor (communication step 1e-4 s, inputs held), each step
    of the gallery's pressure is the exact solution of C_g dp/dt = Q_p − k_r (p − p_c) − Q_b with
    the bearings' draw Q_b held at what the slider-crank reported at the step's start,
    p⁺ = p* + (p − p*) exp(−h k_r/C_g), p* = p_c + (Q_p − Q_b)/k_r, within 1e-5 of the largest
    step's change (measured: 8e-7, the internal steps' truncation); the slider-crank reads the
    pressure the circuit had at the step's start (the Jacobi hold); the bearings' draw moves the
    pressure by more than 0.1 bar over the cycle."""
    start = {v.name: v.start for v in read_model_description(str(CIRCUIT_FMU)).modelVariables}
    q_p, p_c, k_r, v_g, beta = (float(start[n]) for n in ["pump.flow", "relief.pressure",
                                                          "relief.conductance", "gallery.volume",
                                                          "gallery.bulkModulus"])
    p = np.array([v[PRESSURE] for _, v in fmpy_rows])
    draw = np.array([sum(v[f] for f in FLOWS) for _, v in fmpy_rows])
    steady = p_c + (q_p - draw[:-1]) / k_r
    exact = steady + (p[:-1] - steady) * math.exp(-STEP * k_r * beta / v_g)
    assert p.min() > p_c
    change = np.abs(np.diff(p)).max()
    error = np.abs(p[1:] - exact).max()
    print(f"largest change per step {change:.1f} Pa, largest error {error:.2e} Pa")
    assert error <= 1e-5 * change
    held = np.array([v["sliderCrank.oil.supplyPressure"] for _, v in fmpy_rows])
    assert np.array_equal(held[1:], p[:-1])
    assert np.ptp(p) > 1e4


def libcosim_run(execution):
    """The gallery pressure and the bearings' oil flows at every communication point of a libcosim
    execution."""
    from libcosimpy.CosimObserver import CosimObserver

    index = {info.name.decode(): info.index for info in execution.slave_infos()}
    circuit = Session(CIRCUIT_FMU, "names-circuit").vr
    crank = Session(CRANK_FMU, "names-crank").vr
    observer = CosimObserver.create_last_value()
    execution.add_observer(observer)
    rows = []
    for k in range(1, round(STOP / STEP) + 1):
        assert execution.simulate_until(target_time=k * NS)
        (pressure,) = observer.last_real_values(index["lubricationCircuit"],
                                                [circuit["oil.supplyPressure"]])
        flows = observer.last_real_values(index["sliderCrank"],
                                          [crank[f.split(".", 1)[1]] for f in FLOWS])
        rows.append([pressure, *flows])
    return np.array(rows)


def test_libcosim_from_ssp_and_osp_and_the_fmpy_masters_run_the_system_alike(fmpy_rows):
    """Two revolutions of the compressor fed by the circuit, communication step 1e-4 s, Jacobi
    coupling: libcosim's fixed-step algorithm from the SSP and from the OSP file, and the package's
    fmpy master with the FMI 2.0 and with the FMI 3.0 FMUs, give the same gallery pressure and
    bearing flows at every point to 1e-9 relative (as measured: bit for bit)."""
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level

    def table(rows):
        return np.array([[v[PRESSURE], *(v[f] for f in FLOWS)] for _, v in rows[1:]])

    log_output_level(CosimLogLevel.ERROR)
    reference = table(fmpy_rows)
    runs = {
        "libcosim OSP": libcosim_run(CosimExecution.from_osp_config_file(str(OSP))),
        "libcosim SSP": libcosim_run(CosimExecution.from_ssp_file(str(SSP), step_size=NS)),
        "fmpy master, FMI 3": table(lube_system.run(STEP, STOP, fmi3=True)),
    }
    for name, rows in runs.items():
        assert rows.shape == reference.shape, name
        error = np.abs(rows - reference) / np.abs(reference).max(axis=0)
        assert error.max() <= 1e-9, (name, error.max())
