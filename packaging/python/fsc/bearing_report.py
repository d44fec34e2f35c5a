"""The bearing report: a machine run through the FMU for a number of load cycles, and what a bearing
designer reads off each clearance joint over the last complete cycle.

    python -m fsc bearing-report MACHINE.toml [--out DIR] [--cycles N] [--fmu PATH]

A machine file names the FMU's parameters (the start values of the run) and, optionally, the run:

    fmu = "../target/fmu/FlexibleSliderCrank.fmu"   # relative to the machine file (optional)
    cycles = 3                                      # load cycles to run (default 3)
    points_per_cycle = 720                          # communication points per cycle (default 720)

    [parameters]
    "crank.length" = 0.03
    "crankPin.model" = "lubricated"                 # a switch by item name or number
    "slider.forceTable" = "compression.csv"         # a file, relative to the machine file

    [limits]                                        # the bearing maker's limits (optional, SI)
    specific_load = 40e6                            # Pa, largest F/(B D) the lining carries
    temperature = 393.15                            # K, hottest film
    film_ratio = 3.0                                # smallest h_min/sigma
    film_thickness = 3e-6                           # m, smallest film (else ISO 7902-3's h_lim)

For every joint that is not ideal the report draws the polar load diagram (the force on the bearing
in the ground's frame and in the frame of the body that carries the bearing: the ground for the main
bearing, the rod's big-end eye for the crank pin, the rod for the rod-slider joint), with crank-angle
marks every 60°, the journal's orbit in its clearance circle, and for a lubricated joint the film
thickness, film pressure, friction power and oil flow (with the feed's share where it is fed) over
the crank angle of the last complete cycle — with its film temperature and viscosity where it has a
heat balance, and the asperities' load where its surfaces are rough — with the FMU's cycle results
(`<joint>.filmThicknessMinCycle` …) in a table, and a table of the operating limits a designer
checks (`LIMITS`: the largest specific load, the smallest film against ISO 7902-3's limit for the
journal's size and sliding speed, the film ratio on rough surfaces, the hottest film), each with its
limit and where the limit comes from; a dry joint's figure and tables leave out the film. The page
names each joint's models (film, thermal, roughness and feed). The tables and the pictures are of
the same cycle: the FMU's cycle results describe the cycle the crank angle last completed, which is
the one drawn, wherever the run starts and ends. It
writes one PNG per joint and `index.html` into the output directory (default
`target/bearing-report/<machine name>`), and shows its progress while the FMU runs.
"""
import html
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from fmpy import read_model_description  # noqa: E402
from fmpy.fmi1 import FMICallException  # noqa: E402
from tqdm import tqdm  # noqa: E402

from .session import Session, errors  # noqa: E402
from .study import StudyError, _check_value, _variables  # noqa: E402

#: Each joint: its prefix, its name, the sign that turns its force output into the force on its
#: bearing, and the moving body that carries its bearing (None: the ground).
JOINTS = [
    ("mainBearing", "Main bearing", -1.0, None),
    ("crankPin", "Crank pin", 1.0, "rod"),
    ("joint", "Rod–slider joint", -1.0, "rod"),
]
#: Each joint's outputs the report reads at every communication point.
SERIES = ["forceX", "forceY", "forcePeak", "eccentricityX", "eccentricityY", "filmThicknessMin",
          "filmPressurePeak", "frictionPower", "oilFlow", "feedFlow", "filmTemperature",
          "viscosityEffective", "asperityForce"]
#: The cycle results, with their unit in the report, the factor from SI and whether they describe
#: the film (left out for a dry joint).
CYCLE_RESULTS = [
    ("filmThicknessMinCycle", "smallest film thickness", "µm", 1e6, True),
    ("filmThicknessMinCycleAngle", "… at crank angle", "°", 1.0, True),
    ("filmPressurePeakCycle", "largest film pressure", "MPa", 1e-6, True),
    ("filmPressurePeakCycleAngle", "… at crank angle", "°", 1.0, True),
    ("forcePeakCycle", "largest force", "kN", 1e-3, False),
    ("forcePeakCycleAngle", "… at crank angle", "°", 1.0, False),
    ("frictionPowerMeanCycle", "mean friction power", "W", 1.0, False),
    ("oilFlowMeanCycle", "mean oil flow", "cm³/s", 1e6, True),
    ("filmTemperatureMaxCycle", "hottest film (heat balance)", "°C", 1.0, True),
    ("asperityForcePeakCycle", "largest asperity load (rough surfaces)", "N", 1.0, True),
    ("metalContactFractionCycle", "time in dry metal contact", "%", 100.0, False),
]
#: Each joint's model switches the page names, and their items.
MODELS = [("model", ["ideal", "dry", "lubricated"]), ("filmModel", ["short", "finite"]),
          ("thermalModel", ["isoviscous", "heat balance"]),
          ("feed", ["unfed", "feed hole", "circumferential feed groove", "axial feed groove"]),
          ("feedLocation", ["shell", "journal"])]
#: Each joint's parameters the report reads beside its model switches.
GEOMETRY = ["clearance", "roughness", "journalRadius", "bearingLength", "feedPosition",
            "feedDiameter"]

#: The smallest permissible film thickness h_lim [µm] of ISO 7902-3 (and DIN 31652-3) by the
#: shaft's diameter, rows up to 63, 160, 400, 1000 and 2500 mm (the first row also below 24 mm,
#: which the standard leaves out), and the journal's sliding speed, columns up to 1, 3, 10, 30 m/s
#: and above: guide values for finely finished, well-aligned steel journals.
FILM_LIMIT_DIAMETERS = [63e-3, 160e-3, 400e-3, 1000e-3]
FILM_LIMIT_SPEEDS = [1.0, 3.0, 10.0, 30.0]
FILM_LIMITS = [[3, 4, 5, 7, 10], [4, 5, 7, 9, 12], [6, 7, 9, 11, 14], [8, 9, 11, 13, 16],
               [10, 12, 14, 16, 18]]
#: The operating limits the report checks: their default value (SI) and where it comes from. A
#: machine file's [limits] table replaces a default with the bearing maker's figure (the film
#: thickness's default is ISO 7902-3's table, above).
LIMITS = {
    "specific_load": (25e6, "ISO 7902-3 / DIN 31652-3: the largest guide value of the mean "
                            "specific load for tin- and lead-bronze and aluminium-tin linings "
                            "(white metal: 15 MPa); dynamically loaded bearings are rated by "
                            "their lining's fatigue strength, the bearing maker's figure"),
    "film_thickness": (None, "ISO 7902-3 / DIN 31652-3: h_lim by the journal's diameter and its "
                             "mean sliding speed over the cycle"),
    "film_ratio": (3.0, "h_min/σ ≥ 3: a full film over Gaussian surfaces, below it mixed "
                        "lubrication (Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film "
                        "Lubrication, 2004)"),
    "temperature": (383.15, "ISO 7902-3 / DIN 31652-3: the guide value of the largest bearing "
                            "temperature of a pressure-fed bearing (100–115 °C)"),
}


@dataclass
class Machine:
    """A checked machine file."""
    name: str
    fmu: Path
    parameters: dict
    cycles: int
    points_per_cycle: int
    #: The operating limits the report checks: `LIMITS`' keys, each (value, source); a value None
    #: is ISO 7902-3's film limit.
    limits: dict


def load(path, fmu=None, cycles=None) -> Machine:
    """The machine of the file at `path`, its parameters checked against the FMU's model
    description (a StudyError names a wrong entry)."""
    path = Path(path)
    spec = tomllib.loads(path.read_text())
    base = path.parent
    fmu = Path(fmu) if fmu else base / spec.get("fmu", "../target/fmu/FlexibleSliderCrank.fmu")
    if not fmu.is_file():
        raise StudyError(f"{path}: no FMU at {fmu} (build it: cargo run --release -p packaging)")
    variables = _variables(read_model_description(str(fmu)))
    parameters = {}
    for name, value in spec.get("parameters", {}).items():
        value = _check_value(str(path), name, value, variables)
        if variables[name].type == "String" and value:
            file = base / value
            if not file.is_file():
                raise StudyError(f"{path}: {name} names {value}, which is not a file next to it")
            value = str(file.resolve())
        parameters[name] = value
    limits = dict(LIMITS)
    for name, value in spec.get("limits", {}).items():
        if name not in LIMITS:
            raise StudyError(f"{path}: [limits] {name} is not one of {', '.join(LIMITS)}")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value > 0:
            raise StudyError(f"{path}: [limits] {name} = {value!r} is not a positive number")
        limits[name] = (float(value), f"the machine file ({path.name})")
    cycles = int(cycles or spec.get("cycles", 3))
    points = int(spec.get("points_per_cycle", 720))
    if cycles < 2 or points < 36:
        raise StudyError(f"{path}: cycles = {cycles} (at least 2: the first settles) and "
                         f"points_per_cycle = {points} (at least 36)")
    return Machine(path.stem, fmu, parameters, cycles, points, limits)


def run(machine: Machine, progress=True) -> dict:
    """Runs the machine for its cycles: {name: array} of the crank angle, time, slider position and
    every joint's series at each communication point, and the cycle results and parameters at the
    end (scalars)."""
    session = Session(machine.fmu, f"bearing-report-{machine.name}")
    try:
        data = _run(machine, session, progress)
    except FMICallException as e:
        failed = errors(session.fmu.instanceName)
        session.fmu.freeInstance()
        raise StudyError(f"{machine.name}: {failed[-1] if failed else e}") from None
    session.free()
    return data


def _run(machine: Machine, session: Session, progress: bool) -> dict:
    """`run` on an instantiated session."""
    session.set(machine.parameters)
    session.initialize()
    value = session.get
    table = value("slider.forceTable") if "slider.forceTable" in session.vr else ""
    period = math.radians(value("slider.forceTablePeriod") if table else 360.0)
    speed = value("drive.speed") if value("drive.mode") == 1 else value("crank.speed")
    if speed == 0:
        raise StudyError(f"{machine.name}: the crank does not turn (drive.speed = 0)")
    step = period / abs(speed) / machine.points_per_cycle
    names = ["time", "crank.angle", "slider.position"] + [
        f"{prefix}.{s}" for prefix, *_ in JOINTS for s in SERIES]
    vrs = [session.vr[n] for n in names[1:]]
    rows = []
    start = value("crank.angle")
    t = 0.0
    total = machine.cycles * machine.points_per_cycle
    bar = tqdm(total=total, desc=f"{machine.name}: {machine.cycles} cycles", unit="step",
               disable=not progress)
    while True:
        rows.append([t] + list(session.fmu.getReal(vrs)))
        if abs(rows[-1][1] - start) >= machine.cycles * period or len(rows) > 4 * total:
            break
        session.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=step)
        t += step
        bar.update(1)
    bar.close()
    data = {n: np.array(c) for n, c in zip(names, zip(*rows))}
    for prefix, *_ in JOINTS:
        for name in GEOMETRY + [switch for switch, _ in MODELS]:
            data[f"{prefix}.{name}"] = value(f"{prefix}.{name}")
        for name, *_ in CYCLE_RESULTS:
            data[f"{prefix}.{name}"] = value(f"{prefix}.{name}")
    for name in ["crank.length", "slider.offset", "solver.warnings", "cycle.number"]:
        data[name] = value(name)
    data["period"] = period
    return data


def last_cycle(data: dict) -> np.ndarray:
    """The rows of the last complete load cycle: those whose crank angle lies between the last two
    multiples of the period the crank angle crossed (the first row's interval begins before)."""
    k = np.floor(data["crank.angle"] / data["period"])
    boundaries = np.flatnonzero(np.diff(k) != 0) + 1
    if len(boundaries) < 2:
        raise StudyError("no complete load cycle: run more cycles")
    return np.arange(boundaries[-2], boundaries[-1])


def rod_angle(data: dict) -> np.ndarray:
    """The rod's direction from the crank pin to the slider pin [rad] (rigid geometry)."""
    r, e = data["crank.length"], data["slider.offset"]
    theta = data["crank.angle"]
    return np.arctan2(e - r * np.sin(theta), data["slider.position"] - r * np.cos(theta))


def _load_diagram(a, x, y, angles, label):
    """A polar load diagram on axes `a`: the force's path with crank-angle marks every 60°, on equal
    and equally long axes."""
    a.plot(x, y, lw=0.9)
    a.plot([0], [0], "k+")
    for mark in range(0, 360, 60):
        k = int(np.argmin(np.abs((angles - mark + 180.0) % 360.0 - 180.0)))
        a.plot(x[k], y[k], "o", ms=3, color="C1")
        a.annotate(f"{mark}°", (x[k], y[k]), textcoords="offset points", xytext=(4, 4), fontsize=8)
    reach = 1.1 * max(np.max(np.abs(x)), np.max(np.abs(y)), 1e-9)
    a.set(xlim=(-reach, reach), ylim=(-reach, reach), aspect="equal", xlabel="x [kN]",
          ylabel="y [kN]", title=f"Force on the bearing, {label}")
    a.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
    a.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))


def plot_joint(data: dict, rows: np.ndarray, prefix: str, title: str, sign: float, body,
               path: Path):
    """One joint's figure: load diagrams and orbit, and for a lubricated joint the film over the
    last cycle (its temperature and viscosity with a heat balance, the asperities' load on rough
    surfaces)."""
    deg = np.degrees(np.mod(data["crank.angle"][rows], data["period"]))
    fx = sign * data[f"{prefix}.forceX"][rows] / 1e3
    fy = sign * data[f"{prefix}.forceY"][rows] / 1e3
    clearance = data[f"{prefix}.clearance"]
    lubricated = data[f"{prefix}.model"] == 3
    heated = lubricated and data[f"{prefix}.thermalModel"] == 2
    rough = lubricated and data[f"{prefix}.roughness"] > 0
    extra = int(heated or rough)
    fig, ax = plt.subplots(1 + int(lubricated) + extra, 3,
                           figsize=(15, 4.6 * (1 + int(lubricated) + extra)), squeeze=False)
    _load_diagram(ax[0, 0], fx, fy, deg, "ground's frame")
    if body is None:
        ax[0, 1].set_axis_off()
    else:
        frame = rod_angle(data)[rows]
        c, s = np.cos(frame), np.sin(frame)
        shell = "the rod's big-end eye" if prefix == "crankPin" else f"the {body}"
        _load_diagram(ax[0, 1], c * fx + s * fy, -s * fx + c * fy, deg, f"frame of {shell}")
    phi = np.linspace(0, 2 * np.pi, 200)
    ax[0, 2].plot(np.cos(phi), np.sin(phi), "k--", lw=0.8, label="clearance circle")
    ax[0, 2].plot(data[f"{prefix}.eccentricityX"][rows] / clearance,
                  data[f"{prefix}.eccentricityY"][rows] / clearance, lw=0.9, color="C2",
                  label="journal centre")
    ax[0, 2].set(xlabel="x / c", ylabel="y / c", aspect="equal", title="Journal orbit")
    ax[0, 2].legend(loc="lower right", fontsize=8)
    angle = "crank angle in the cycle [°]"
    if lubricated:
        ax[1, 0].plot(deg, 1e6 * data[f"{prefix}.filmThicknessMin"][rows], lw=0.9, color="C3")
        ax[1, 0].set(xlabel=angle, ylabel="smallest film thickness [µm]", title="Film thickness")
        ax[1, 1].plot(deg, 1e-6 * data[f"{prefix}.filmPressurePeak"][rows], lw=0.9, color="C4")
        ax[1, 1].set(xlabel=angle, ylabel="largest film pressure [MPa]", title="Film pressure")
        ax[1, 2].plot(deg, data[f"{prefix}.frictionPower"][rows], lw=0.9, color="C5")
        ax[1, 2].set(xlabel=angle, ylabel="friction power [W]", title="Friction power and oil flow")
        flow = ax[1, 2].twinx()
        flow.plot(deg, 1e6 * data[f"{prefix}.oilFlow"][rows], lw=0.9, color="C0",
                  label="oil flow")
        if data[f"{prefix}.feed"] != 1:
            flow.plot(deg, 1e6 * data[f"{prefix}.feedFlow"][rows], lw=0.9, ls="--", color="C0",
                      label="the feed's share")
            flow.legend(loc="upper right", fontsize=8)
        flow.set_ylabel("oil flow [cm³/s]", color="C0")
    if extra:
        row = ax[2]
        if heated:
            row[0].plot(deg, data[f"{prefix}.filmTemperature"][rows] - 273.15, lw=0.9, color="C3")
            row[0].set(xlabel=angle, ylabel="film temperature [°C]",
                       title="Film temperature (heat balance)")
            row[1].plot(deg, 1e3 * data[f"{prefix}.viscosityEffective"][rows], lw=0.9, color="C4")
            row[1].set(xlabel=angle, ylabel="viscosity [mPa s]", title="The oil's viscosity")
        else:
            row[0].set_axis_off()
            row[1].set_axis_off()
        if rough:
            row[2].plot(deg, data[f"{prefix}.asperityForce"][rows], lw=0.9, color="C5")
            row[2].set(xlabel=angle, ylabel="asperity load [N]",
                       title="Rough surfaces: the asperities' load")
        else:
            row[2].set_axis_off()
    for a in ax.flat:
        a.grid(alpha=0.3)
    fig.suptitle(f"{title}: load cycle {int(data['cycle.number'])}, the last complete one")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def models(data: dict, prefix: str) -> str:
    """The joint's models as the page names them."""
    model = data[f"{prefix}.model"]
    names = [dict(MODELS)["model"][int(model) - 1]]
    if model == 3:
        names.append(f"{dict(MODELS)['filmModel'][int(data[f'{prefix}.filmModel']) - 1]} film")
        names.append(dict(MODELS)["thermalModel"][int(data[f"{prefix}.thermalModel"]) - 1])
        roughness = data[f"{prefix}.roughness"]
        names.append(f"roughness {roughness * 1e6:.3g} µm" if roughness > 0 else "smooth")
        feed = int(data[f"{prefix}.feed"])
        name = dict(MODELS)["feed"][feed - 1]
        size = data[f"{prefix}.feedDiameter"] * 1e3
        if feed == 2:
            name += f" {size:.3g} mm"
        elif feed > 2:
            name += f" {size:.3g} mm wide"
        if feed in (2, 4):
            body = dict(MODELS)["feedLocation"][int(data[f"{prefix}.feedLocation"]) - 1]
            name += f" in the {body} at {math.degrees(data[f'{prefix}.feedPosition']):.4g}°"
        names.append(name)
    return ", ".join(names)


def sliding_speed(data: dict, rows: np.ndarray, prefix: str) -> float:
    """The journal's mean sliding speed over the cycle's `rows`, R |ω_J − ω_B| [m/s]: the crank's
    rate in the main bearing, the crank's relative to the rod's in the crank pin, the rod's in the
    rod–slider joint (rigid geometry)."""
    t = data["time"]
    crank = np.gradient(data["crank.angle"], t)
    rod = np.gradient(np.unwrap(rod_angle(data)), t)
    relative = {"mainBearing": crank, "crankPin": crank - rod, "joint": rod}[prefix]
    return data[f"{prefix}.journalRadius"] * float(np.mean(np.abs(relative[rows])))


def film_limit(diameter: float, speed: float) -> float:
    """ISO 7902-3's smallest permissible film thickness [m] for a journal of `diameter` [m] at the
    sliding speed `speed` [m/s] (`FILM_LIMITS`)."""
    row = int(np.searchsorted(FILM_LIMIT_DIAMETERS, diameter))
    column = int(np.searchsorted(FILM_LIMIT_SPEEDS, speed))
    return FILM_LIMITS[min(row, len(FILM_LIMITS) - 1)][column] / 1e6


def operating_limits(machine: Machine, data: dict, rows: np.ndarray, prefix: str) -> list:
    """The joint's operating limits over the cycle's `rows`: (check, value, limit, within, source)
    for the largest specific load, and for a lubricated joint the smallest film, the film ratio
    (rough surfaces) and the hottest film (heat balance)."""
    radius, length = data[f"{prefix}.journalRadius"], data[f"{prefix}.bearingLength"]
    (load_limit, load_source) = machine.limits["specific_load"]
    load = data[f"{prefix}.forcePeakCycle"] / (2.0 * radius * length)
    checks = [("largest specific load F/(B D)", f"{load * 1e-6:.3g} MPa",
               f"{load_limit * 1e-6:.3g} MPa", load <= load_limit, load_source)]
    if data[f"{prefix}.model"] != 3:
        return checks
    film = data[f"{prefix}.filmThicknessMinCycle"]
    (film_min, source) = machine.limits["film_thickness"]
    if film_min is None:
        speed = sliding_speed(data, rows, prefix)
        film_min = film_limit(2.0 * radius, speed)
        source += f" ({2e3 * radius:.3g} mm, {speed:.3g} m/s)"
    checks.append(("smallest film h_min", f"{film * 1e6:.3g} µm", f"{film_min * 1e6:.3g} µm",
                   film >= film_min, source))
    roughness = data[f"{prefix}.roughness"]
    if roughness > 0:
        (ratio_min, source) = machine.limits["film_ratio"]
        checks.append(("smallest film ratio h_min/σ", f"{film / roughness:.3g}",
                       f"{ratio_min:.3g}", film >= ratio_min * roughness, source))
    if data[f"{prefix}.thermalModel"] == 2:
        hottest = data[f"{prefix}.filmTemperatureMaxCycle"]
        (hottest_max, source) = machine.limits["temperature"]
        checks.append(("hottest film", f"{hottest - 273.15:.4g} °C",
                       f"{hottest_max - 273.15:.4g} °C", hottest <= hottest_max, source))
    return checks


def write(machine: Machine, data: dict, out: Path) -> Path:
    """The PNG of each clearance joint and index.html; returns the page's path."""
    out.mkdir(parents=True, exist_ok=True)
    rows = last_cycle(data)
    sections = []
    for prefix, title, sign, body in JOINTS:
        if data[f"{prefix}.model"] == 1:
            continue
        plot_joint(data, rows, prefix, title, sign, body, out / f"{prefix}.png")
        lubricated = data[f"{prefix}.model"] == 3
        shown = [r for r in CYCLE_RESULTS if lubricated or not r[4]]
        if data[f"{prefix}.thermalModel"] != 2:
            shown = [r for r in shown if r[0] != "filmTemperatureMaxCycle"]
        if data[f"{prefix}.roughness"] == 0:
            shown = [r for r in shown if r[0] != "asperityForcePeakCycle"]
        cells = "".join(
            f"<tr><td>{html.escape(label)}</td><td><code>{prefix}.{name}</code></td>"
            f"<td>{(data[f'{prefix}.{name}'] - (273.15 if unit == '°C' else 0.0)) * factor:.4g} "
            f"{unit}</td></tr>"
            for name, label, unit, factor, _ in shown)
        checks = "".join(
            f"<tr><td>{html.escape(check)}</td><td>{html.escape(value)}</td>"
            f"<td>{html.escape(limit)}</td><td>{'within' if within else '<b>beyond</b>'}</td>"
            f"<td>{html.escape(source)}</td></tr>"
            for check, value, limit, within, source in operating_limits(machine, data, rows,
                                                                          prefix))
        sections.append(f"<h2>{html.escape(title)}</h2>\n"
                        f"<p>{html.escape(models(data, prefix))}</p>\n<table>{cells}</table>\n"
                        "<h3>Operating limits</h3>\n<table><tr><th>check</th><th>this cycle</th>"
                        f"<th>limit</th><th></th><th>the limit's source</th></tr>{checks}</table>\n"
                        f'<p><img src="{prefix}.png" alt="{html.escape(title)}" width="100%"></p>')
    if not sections:
        sections.append("<p>Every joint is ideal: no bearing to report.</p>")
    parameters = "".join(f"<tr><td><code>{html.escape(n)}</code></td><td>{html.escape(str(v))}"
                         "</td></tr>" for n, v in machine.parameters.items())
    page = out / "index.html"
    page.write_text(
        "<!DOCTYPE html><html><head><meta charset='utf-8'>"
        f"<title>Bearing report: {html.escape(machine.name)}</title>"
        "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
        "td{padding:2px 12px}</style></head><body>"
        f"<h1>Bearing report: {html.escape(machine.name)}</h1>"
        f"<p>{machine.cycles} load cycles of {math.degrees(data['period']):.0f}° "
        f"({data['time'][-1]:.4g} s), {machine.points_per_cycle} points per cycle; the results "
        f"and the pictures are those of the last complete cycle, cycle "
        f"{int(data['cycle.number'])}. FMU warnings: {int(data['solver.warnings'])}.</p>"
        + "\n".join(sections)
        + f"<h2>Parameters</h2><table>{parameters}</table></body></html>")
    return page
