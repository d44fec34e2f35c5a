"""The motor-crank system: the DC-motor FMU, the system run by libcosim (from the SSP and from the
OSP system structure), by fmpy's own SSP simulation and by a plain fmpy master, and the coupling
error of held and interpolated inputs."""
import os

import numpy as np
import pytest
from fmpy.ssp.simulation import simulate_ssp
from fmpy.ssp.ssd import Parameter, ParameterSet, find_components, read_ssd
from fmpy.validation import validate_fmu

from fsc import dependencies, system
from fsc.session import Session

from conftest import ROOT

FMUS = ROOT / "target" / "fmu"
CRANK_FMU = FMUS / system.CRANK
MOTOR_FMU = FMUS / system.MOTOR
SSP = FMUS / "MotorCrank.ssp"
OSP = FMUS / "motor-crank" / "OspSystemStructure.xml"
SSD = ROOT / "systems" / "motor-crank" / "SystemStructure.ssd"

STOP, STEP = 0.024, 1e-4
NS = 100_000  # STEP in libcosim's nanoseconds


def test_both_fmus_pass_fmpy_validation():
    assert validate_fmu(str(MOTOR_FMU)) == []
    assert validate_fmu(str(CRANK_FMU)) == []


def initialized_motor(parameters=None):
    """A motor instance with `parameters` set, after initialization."""
    motor = Session(MOTOR_FMU, "motor")
    motor.set(parameters or {})
    motor.fmu.enterInitializationMode()
    motor.fmu.exitInitializationMode()
    return motor


def test_motor_starts_in_steady_state_at_its_set_point():
    motor = initialized_motor()
    speed = motor.get("speed.setPoint")
    assert motor.get("motor.speed") == speed
    assert motor.get("shaft.torque") == 0.0
    friction, k = motor.get("motor.friction"), motor.get("motor.torqueConstant")
    assert abs(motor.get("motor.current") - friction * speed / k) < 1e-12
    # A constant load speed equal to the set-point leaves it there.
    for n in range(10):
        motor.fmu.doStep(n * STEP, STEP)
    assert abs(motor.get("motor.speed") - speed) < 1e-9 * speed
    motor.free()


def test_motor_declared_initial_dependencies_are_the_measured_ones():
    """ModelStructure/InitialUnknowns of the motor: perturbing each input and parameter in
    initialization mode changes exactly the declared outputs, with a shaft torque at the start, a
    controller without integral action, a supply at its voltage limit and a load off the
    set-point."""
    configurations = [{}, {"shaft.initialTorque": 5.0},
                      {"shaft.initialTorque": 5.0, "controller.integralGain": 0.0},
                      {"shaft.initialTorque": 5.0, "supply.voltageLimit": 10.0},
                      {"shaft.initialTorque": -3.0, "shaft.speed": 300.0}]
    measured, n = dependencies.measure(str(MOTOR_FMU), configurations)
    assert n == len(configurations)
    assert measured == dependencies.declared(str(MOTOR_FMU))


def test_motor_directional_derivatives_are_its_gains():
    """fmi2GetDirectionalDerivative of the motor: ∂shaft.torque/∂shaft.speed = −shaft.damping,
    ∂motor.voltage/∂speed.setPoint = controller.gain inside the voltage limit and 0 at it, every
    other entry 0; equal to central differences (the outputs are affine in the inputs)."""
    for limit in (200.0, 10.0):
        motor = initialized_motor({"supply.voltageLimit": limit})
        for n in range(5):
            motor.set({"shaft.speed": 500.0})
            motor.fmu.doStep(n * STEP, STEP)
        outputs = ["shaft.torque", "motor.speed", "motor.current", "motor.voltage", "shaft.twist"]
        ov = [motor.vr[o] for o in outputs]
        for u in ("shaft.speed", "speed.setPoint"):
            d = motor.fmu.getDirectionalDerivative(ov, [motor.vr[u]], [1.0])
            x, h = motor.get(u), 1e-3
            motor.set({u: x + h})
            plus = np.array(motor.fmu.getReal(ov))
            motor.set({u: x - h})
            minus = np.array(motor.fmu.getReal(ov))
            motor.set({u: x})
            assert np.allclose(d, (plus - minus) / (2 * h), rtol=1e-8, atol=1e-9), (limit, u, d)
            expected = {("shaft.torque", "shaft.speed"): -motor.get("shaft.damping"),
                        ("motor.voltage", "speed.setPoint"):
                            motor.get("controller.gain") if limit > 100.0 else 0.0}
            assert list(d) == [expected.get((o, u), 0.0) for o in outputs]
        motor.free()


def test_motor_state_round_trips_and_an_old_format_is_rejected():
    """The motor's serialized state (its warnings count and checked step included) restores into a
    new instance bit for bit; a state of another format version is refused (fmi2Error; the
    message names both versions, tests/fmi)."""
    def started():
        return initialized_motor(system.MOTOR_PARAMETERS)
    a = started()
    a.set({"shaft.speed": 500.0})
    a.fmu.doStep(0.0, 4e-4)
    assert a.get("solver.warnings") == 1
    data = a.fmu.serializeFMUstate(a.fmu.getFMUstate())
    b = started()
    b.fmu.setFMUstate(b.fmu.deSerializeFMUstate(data))
    for s in (a, b):
        s.fmu.doStep(4e-4, 4e-4)
    outputs = ["shaft.torque", "motor.speed", "motor.current", "motor.voltage", "shaft.twist"]
    assert [a.get(o) for o in outputs] == [b.get(o) for o in outputs]
    assert a.get("solver.warnings") == b.get("solver.warnings") == 1
    # The same bytes with format version 1 and a valid checksum (FNV-1a 64 of all before it).
    old = bytearray(data[:-8])
    old[4:8] = (1).to_bytes(4, "little")
    checksum = 0xcbf29ce484222325
    for byte in old:
        checksum = ((checksum ^ byte) * 0x100000001b3) % (1 << 64)
    c = started()
    with pytest.raises(Exception):
        c.fmu.deSerializeFMUstate(bytes(old) + checksum.to_bytes(8, "little"))
    c.fmu.freeInstance()
    for s in (a, b):
        s.free()


def test_motor_start_follows_the_set_point_until_initialization_ends():
    motor = Session(MOTOR_FMU, "motor")
    motor.fmu.enterInitializationMode()
    assert motor.get("motor.speed") == motor.get("speed.setPoint")
    motor.set({"speed.setPoint": 300.0})
    assert motor.get("motor.speed") == 300.0
    motor.fmu.exitInitializationMode()
    motor.set({"speed.setPoint": 400.0})
    assert motor.get("motor.speed") == 300.0
    motor.free()


def libcosim_run(execution):
    """crank.speed and joint.forcePeak at every communication point of a libcosim execution."""
    from libcosimpy.CosimObserver import CosimObserver

    index = {info.name.decode(): info.index for info in execution.slave_infos()}
    vr = Session(CRANK_FMU, "names").vr
    observer = CosimObserver.create_last_value()
    execution.add_observer(observer)
    rows = []
    for k in range(1, round(STOP / STEP) + 1):
        assert execution.simulate_until(target_time=k * NS)
        rows.append(observer.last_real_values(index["sliderCrank"],
                                              [vr["crank.speed"], vr["joint.forcePeak"]]))
    return np.array(rows)


def fmpy_run(**kwargs):
    rows = system.run(STEP, STOP, outputs=("crank.speed", "joint.forcePeak"), **kwargs)
    return np.array([[v["crank.speed"], v["joint.forcePeak"]] for _, v in rows])


def test_libcosim_from_ssp_and_osp_and_the_fmpy_master_run_the_system_alike():
    """24 ms from 5000 rpm with the controller at its set-point, communication step 1e-4 s, Jacobi
    coupling with the initial outputs exchanged: libcosim's fixed-step algorithm from the SSP and
    from the OSP file and the plain fmpy master agree in crank speed to 1e-9 relative over the
    first 2 ms and within 1 % in the largest joint.forcePeak (as measured: bit for bit)."""
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level

    log_output_level(CosimLogLevel.ERROR)
    runs = {
        "libcosim OSP": libcosim_run(CosimExecution.from_osp_config_file(str(OSP))),
        "libcosim SSP": libcosim_run(CosimExecution.from_ssp_file(str(SSP), step_size=NS)),
        "fmpy master": fmpy_run(),
    }
    reference = runs["fmpy master"]
    first = round(2e-3 / STEP)
    assert reference[:, 1].max() > 1e3  # impacts happen
    for name, rows in runs.items():
        assert rows.shape == reference.shape, name
        speed_error = np.abs(rows[:first, 0] - reference[:first, 0]) / reference[:first, 0]
        assert speed_error.max() <= 1e-9, name
        assert abs(rows[:, 1].max() - reference[:, 1].max()) <= 0.01 * reference[:, 1].max(), name


def test_fmpy_ssp_simulation_runs_the_system_with_connections_starting_at_zero():
    """fmpy's simulate_ssp starts every connection at 0 (not at the initial outputs) and applies
    no parameter bindings itself: given the SSP's bindings, it runs exactly the fmpy master with
    that start."""
    ssd = read_ssd(str(SSP))
    bound = ParameterSet(name="bindings")
    for component in find_components(ssd.system):
        for binding in component.parameterBindings:
            for values in binding.parameterValues:
                for p in values.parameters:
                    bound.parameters.append(Parameter(name=f"{component.name}.{p.name}",
                                                      type=p.type, value=p.value))
    result = simulate_ssp(str(SSP), stop_time=STOP, step_size=STEP, parameter_set=bound)
    expected = fmpy_run(zero_start=True)
    # (fmpy accumulates time in floating point: its loop takes one step past the stop time)
    n = len(expected)
    assert len(result) >= n
    assert np.array_equal(result["sliderCrank.crank.speed"][:n], expected[:, 0])
    assert np.array_equal(result["sliderCrank.joint.forcePeak"][:n], expected[:, 1])


def test_the_ssp_carries_what_omsimulator_needs():
    """The SSD passes the SSP 1.0 schema (fmpy's read_ssd validates it) and carries OMSimulator's
    annotation with its fixed-step master ("oms-ma") at the system's 1e-4 s step; no component
    name followed by a dot starts one of its parameter bindings' or connectors' names (OMSimulator
    strips such a prefix from binding names), and the OSP file names its simulators alike."""
    from lxml import etree

    read_ssd(str(SSP))
    ns = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
          "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
          "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
          "oms": "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd"}
    root = etree.parse(str(SSD)).getroot()
    masters = root.findall("ssd:System/ssd:Annotations/ssc:Annotation[@type='org.openmodelica']"
                           "/oms:Annotations/oms:SimulationInformation/oms:FixedStepMaster", ns)
    assert [float(m.get("stepSize")) for m in masters] == [STEP]
    # OMSimulator's importer selects its master by this name and refuses the system without it.
    assert [m.get("description") for m in masters] == ["oms-ma"]
    components = root.findall("ssd:System/ssd:Elements/ssd:Component", ns)
    assert {c.get("name") for c in components} == {"dcMotor", "sliderCrank"}
    for c in components:
        names = [p.get("name") for p in c.findall(".//ssv:Parameter", ns)]
        names += [k.get("name") for k in c.findall("ssd:Connectors/ssd:Connector", ns)]
        assert names and not [n for n in names if n.startswith(c.get("name") + ".")], names
    osp = etree.parse(str(OSP)).getroot()
    assert {s.get("name") for s in osp.iter("{*}Simulator")} == {"dcMotor", "sliderCrank"}


def test_the_documented_stable_steps_hold():
    """Over 0.2 s with held inputs the system stays stable at the largest documented communication
    steps (Jacobi 3e-4 s, Gauss-Seidel 1e-3 s) and diverges just beyond them (5e-4 s, 3e-3 s)."""
    table = system.stability(steps=(3e-4, 5e-4, 1e-3, 3e-3))
    assert [table["jacobi"][h][2] for h in (3e-4, 5e-4)] == [True, False]
    assert [table["gauss-seidel"][h][2] for h in (1e-3, 3e-3)] == [True, False]


def test_the_motor_warns_beyond_the_stable_step():
    """The motor, knowing its load's inertia (shaft.loadInertia, bound in the SSP and the OSP
    file), checks each new communication step for the stability of the shaft's coupling: no
    warning at 1e-4 and 3e-4 s, one (solver.warnings) at the first step of 4e-4 s, and at 1e-3 s,
    where only the motor-first exchange is stable."""
    for h, warnings in ((1e-4, 0), (3e-4, 0), (4e-4, 1), (1e-3, 1)):
        for coupling in ("jacobi", "gauss-seidel"):
            rows = system.run(h, 3 * h, outputs=("dcMotor/solver.warnings",), coupling=coupling)
            assert [v["dcMotor/solver.warnings"] for _, v in rows] == [warnings] * 3, (h, coupling)


def test_first_order_input_derivatives_cut_the_coupling_error():
    """Crank speed at 1 ms against a 2.5e-6 s run with second-order inputs, the crank at
    solver.relativeTolerance 1e-6: first-order input derivatives give at least 2x less error than
    held inputs at communication steps 1e-4, 5e-5 and 1e-5 s."""
    _, errors = system.coupling_errors()
    for step, e in errors.items():
        assert e["order 1"] * 2 <= e["held"], (step, e)


def test_input_derivatives_are_part_of_the_fmu_state():
    """A state taken after fmi2SetRealInputDerivatives and restored later continues with the
    same interpolated input."""
    crank = Session(CRANK_FMU, "crank")
    crank.set(system.CRANK_PARAMETERS)
    crank.fmu.enterInitializationMode()
    crank.fmu.exitInitializationMode()
    vr = crank.vr["drive.torque"]
    crank.fmu.setReal([vr], [5.0])
    crank.fmu.setRealInputDerivatives([vr], [1], [4e4])
    state = crank.fmu.getFMUstate()
    crank.fmu.doStep(0.0, STEP)
    first = crank.get("crank.speed")
    crank.fmu.setFMUstate(state)
    crank.fmu.doStep(0.0, STEP)
    assert crank.get("crank.speed") == first
    crank.fmu.setFMUstate(state)
    crank.fmu.setRealInputDerivatives([vr], [1], [0.0])
    crank.fmu.doStep(0.0, STEP)
    assert crank.get("crank.speed") != first
    crank.fmu.freeFMUstate(state)
    crank.free()
