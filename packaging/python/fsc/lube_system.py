"""The lubrication-circuit system (target/fmu/LubeCrank.ssp, target/fmu/lube-crank/) run by a plain
fmpy master: the circuit's gallery pressure and cooler outlet temperature feed the slider-crank's
bearings (oil.supplyPressure, oil.supplyTemperature), the bearings' oil and heat flows go back to
the circuit.

The master is a Jacobi loop, as libcosim's fixed-step algorithm: in initialization mode, as many
passes as there are FMUs of reading every output and setting it to the inputs it connects to (so
that the circuit starts at the steady pressure for the bearings' draw, and the bearings settle at
that supply); then before every step each FMU's outputs are read and set as the other's inputs,
held over the step, and both FMUs step from the same point. The slider-crank's parameters are those the SSP binds (the
compressor's crank train with its lubricated, heated and fed crank pin and main bearing).

usage: python -m fsc.lube_system [--fmus DIR] [--stop SECONDS] [--plot FILE]
                      prints the supply pressure and temperature, the bearings' oil and heat flows
                      and film temperatures at every 10 ms of a run (default 0.08 s, two
                      revolutions, communication step 1e-4 s); with --plot, also plots them
"""
import argparse
import sys
from pathlib import Path

from lxml import etree

from .session import Session

#: The folder of both FMUs: the packaging step's `target/fmu`, from a clone's root (`--fmus DIR`
#: names another).
FMU_DIR = Path("target") / "fmu"
CRANK = "FlexibleSliderCrank.fmu"
CIRCUIT = "LubricationCircuit.fmu"
#: The system's structure, whose parameter bindings and connections the master applies.
SSD = Path(__file__).resolve().parents[3] / "systems" / "lube-crank" / "SystemStructure.ssd"
NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
      "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues"}


def structure(ssd=SSD):
    """The slider-crank's parameters ({name: value}) and the connections ((from component,
    connector, to component, connector)) of the system structure `ssd`."""
    root = etree.parse(str(ssd)).getroot()
    parameters = {}
    for p in root.iterfind(".//ssd:Component[@name='sliderCrank']//ssv:Parameter", NS):
        (value,) = list(p)
        parameters[p.get("name")] = (int if value.tag.endswith("Integer") else float)(
            value.get("value"))
    connections = [(c.get("startElement"), c.get("startConnector"), c.get("endElement"),
                    c.get("endConnector")) for c in root.iterfind(".//ssd:Connection", NS)]
    return parameters, connections


def run(step, stop, outputs=(), fmi3=False):
    """The system over [0, stop] with communication step `step`: a list of (t, {"<component>.
    <variable>": value}) per communication point (t = 0 included) for every connected variable
    and `outputs` ("sliderCrank.<name>" or "lubricationCircuit.<name>"); `fmi3` runs the FMI 3.0
    FMUs (`fmi3/` beside the FMI 2.0 ones)."""
    parameters, connections = structure()
    folder = FMU_DIR / "fmi3" if fmi3 else FMU_DIR
    sessions = {"lubricationCircuit": Session(folder / CIRCUIT, "circuit"),
                "sliderCrank": Session(folder / CRANK, "crank")}
    sessions["sliderCrank"].set(parameters)
    names = sorted({f"{a}.{x}" for a, x, _, _ in connections} | set(outputs))

    def read():
        return {name: sessions[name.split(".", 1)[0]].get(name.split(".", 1)[1])
                for name in names}

    def exchange():
        values = {(a, x): sessions[a].get(x) for a, x, _, _ in connections}
        for a, x, b, y in connections:
            sessions[b].set({y: values[(a, x)]})

    for s in sessions.values():
        if s.fmi3:
            s.fmu.enterInitializationMode(startTime=0.0)
        else:
            s.fmu.enterInitializationMode()
    for _ in sessions:
        exchange()
    for s in sessions.values():
        s.fmu.exitInitializationMode()
    rows = [(0.0, read())]
    for k in range(round(stop / step)):
        exchange()
        for s in sessions.values():
            s.fmu.doStep(k * step, step)
        rows.append(((k + 1) * step, read()))
    for s in sessions.values():
        s.free()
    return rows


OUTPUTS = ("sliderCrank.crankPin.filmTemperature", "sliderCrank.mainBearing.filmTemperature",
           "lubricationCircuit.relief.flow", "lubricationCircuit.sump.temperature",
           "lubricationCircuit.cooler.heatFlow")


def main():
    global FMU_DIR
    parser = argparse.ArgumentParser(prog="python -m fsc.lube_system")
    parser.add_argument("--fmus", type=Path, default=FMU_DIR)
    parser.add_argument("--stop", type=float, default=0.08)
    parser.add_argument("--plot", type=Path)
    args = parser.parse_args()
    FMU_DIR = args.fmus
    rows = run(1e-4, args.stop, outputs=OUTPUTS)
    print("| t [ms] | supply [bar] | supply [°C] | oil flow main/pin [cm³/s] | heat main/pin [W] | "
          "films main/pin [°C] |")
    print("|---|---|---|---|---|---|")
    for t, v in rows[::100]:
        print(f"| {1e3 * t:.0f} | {1e-5 * v['lubricationCircuit.oil.supplyPressure']:.4f} | "
              f"{v['lubricationCircuit.oil.supplyTemperature'] - 273.15:.3f} | "
              f"{1e6 * v['sliderCrank.mainBearing.oilFlow']:.3f} / "
              f"{1e6 * v['sliderCrank.crankPin.oilFlow']:.3f} | "
              f"{v['sliderCrank.mainBearing.heatFlow']:.2f} / {v['sliderCrank.crankPin.heatFlow']:.2f} | "
              f"{v['sliderCrank.mainBearing.filmTemperature'] - 273.15:.2f} / "
              f"{v['sliderCrank.crankPin.filmTemperature'] - 273.15:.2f} |")
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        t = [1e3 * t for t, _ in rows]
        fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
        ax[0].plot(t, [1e-5 * v["lubricationCircuit.oil.supplyPressure"] for _, v in rows])
        ax[0].set(ylabel="supply pressure [bar]",
                  title="The lubrication circuit feeding the slider-crank's bearings")
        for j, name in [("mainBearing", "main bearing"), ("crankPin", "crank pin")]:
            ax[1].plot(t, [1e6 * v[f"sliderCrank.{j}.oilFlow"] for _, v in rows], label=name)
            ax[2].plot(t, [v[f"sliderCrank.{j}.heatFlow"] for _, v in rows], label=name)
        ax[1].set(ylabel="oil flow [cm³/s]")
        ax[2].set(ylabel="heat to the oil [W]", xlabel="time [ms]")
        for a in ax:
            a.grid(alpha=0.3)
        ax[1].legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=100)
        print(f"wrote {args.plot}")


if __name__ == "__main__":
    sys.exit(main())
