"""The code's layout: no import cycle among the files of a crate, and no source file longer than
about 500 lines of code (tests and the variable tables, which are data, excepted)."""
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
CRATES = ["src", "fmi-core/src", "fmi-export/src", "dc-motor/src", "lube-circuit/src", "packaging/src",
          "fuzz/src"]
#: Longest file, in lines before its unit tests.
MAX_LINES = 520
#: Data tables: one row per FMI variable (the slider-crank's, by component, in a folder).
TABLES = ("src/variables/", "dc-motor/src/variables.rs", "lube-circuit/src/variables.rs")


def modules(crate):
    """Module path -> source without comments and unit tests, for every file of a crate."""
    out = {}
    for path in sorted((ROOT / crate).rglob("*.rs")):
        rel = path.relative_to(ROOT / crate).with_suffix("").as_posix()
        rel = rel[: -len("/mod")] if rel.endswith("/mod") else rel
        name = "" if rel in ("lib", "main") else rel.replace("/", "::")
        text = path.read_text()
        text = re.sub(r"#\[cfg\(test\)\]\s*mod tests \{.*", "", text, flags=re.S)
        out[name] = re.sub(r"//.*", "", text)
    return out


def resolve(files, current, path):
    """The module a `crate::`, `super::` or `self::` path names (its longest module prefix)."""
    parts = path.split("::")
    if parts[0] == "crate":
        base, parts = [], parts[1:]
    elif parts[0] == "super":
        base, parts = (current.split("::")[:-1] if current else []), parts[1:]
        while parts and parts[0] == "super":
            base, parts = base[:-1], parts[1:]
    else:
        base, parts = (current.split("::") if current else []), parts[1:]
    full = base + parts
    for k in range(len(full), 0, -1):
        if "::".join(full[:k]) in files:
            return "::".join(full[:k])
    return None


def imports(files):
    """Module -> the modules it imports from (a path through a module, a grouped import, or a
    path relative to the module naming one of its children)."""
    edges = {}
    for m, src in files.items():
        paths = re.findall(r"\b((?:crate|super|self)(?:::\w+)+)", src)
        for base, group in re.findall(r"\b((?:crate|super|self)(?:::\w+)*)::\{([^}]*)\}", src):
            paths.append(base + "::_")
            paths += [base + "::" + inner for inner in re.findall(r"(\w+)::", group)]
        prefix = m + "::" if m else ""
        for child in files:
            rest = child[len(prefix):]
            if child.startswith(prefix) and child != m and "::" not in rest and \
                    re.search(r"(?<![:\w])" + rest + r"::", src):
                paths.append("self::" + rest)
        targets = {resolve(files, m, p) for p in paths}
        edges[m] = {t for t in targets if t and t != m}
    return edges


def cycles(edges):
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in edges:
        if v not in index:
            visit(v)
    return found


@pytest.mark.parametrize("crate", CRATES)
def test_no_import_cycle(crate):
    assert cycles(imports(modules(crate))) == []


def test_the_cycle_check_sees_a_cycle():
    files = {"": "", "a": "use super::b::X;", "b": "use crate::a::Y;", "c": "use super::{a::Z};"}
    assert cycles(imports(files)) == [["a", "b"]]
    parent = {"": "", "m": "pub use child::T;", "m::child": "use super::U;"}
    assert cycles(imports(parent)) == [["m", "m::child"]]


def test_no_long_source_file():
    long = []
    for crate in CRATES:
        for path in (ROOT / crate).rglob("*.rs"):
            name = path.relative_to(ROOT).as_posix()
            lines = path.read_text().split("\n#[cfg(test)]\nmod tests")[0].count("\n")
            if lines > MAX_LINES and not name.startswith(TABLES):
                long.append(f"{name}: {lines} lines")
    assert not long, "\n".join(long)


def test_the_fmi_layer_sees_only_the_simulation_facade():
    """The slider-crank's FMI model imports the simulation, the parameters, the error type (what
    the library's root re-exports) and the variable table, never the physics modules behind them."""
    files = modules("src")
    facade = {"simulation", "simulation::codec", "params", "error", "variables"}
    found = []
    for module, targets in imports(files).items():
        if module == "fmi" or module.startswith("fmi::"):
            outside = {t for t in targets if not (t == "fmi" or t.startswith("fmi::"))} - facade
            found += [f"{module} imports {t}" for t in sorted(outside)]
    assert not found, "\n".join(found)


def test_no_module_imports_the_fmi_layer():
    """The FMI adapter sits on top: the physics, the parameters and the variable table below it
    never import it (the variable table lies below both)."""
    files = modules("src")
    found = [f"{module} imports {t}" for module, targets in imports(files).items()
             if not (module == "fmi" or module.startswith("fmi::"))
             for t in sorted(targets) if t == "fmi" or t.startswith("fmi::")]
    assert not found, "\n".join(found)


def test_only_the_fmi_adapters_import_the_fmi_versions():
    """The run, the physics and the variable tables import the version-neutral core (`fmi_core`),
    never the crate with the FMI versions' C API (`fmi_export`): only the FMI adapter does
    (src/fmi/ of the slider-crank, fmu.rs and lib.rs of the motor and of the circuit)."""
    found = []
    for crate, adapters in [("src", ("fmi/",)), ("dc-motor/src", ("fmu.rs", "lib.rs")),
                            ("lube-circuit/src", ("fmu.rs", "lib.rs"))]:
        for path in sorted((ROOT / crate).rglob("*.rs")):
            name = path.relative_to(ROOT / crate).as_posix()
            text = re.sub(r"//.*", "", path.read_text())
            if "fmi_export" in text and not name.startswith(adapters):
                found.append(f"{crate}/{name}")
    assert not found, found
    assert "fmi_export" in (ROOT / "src" / "fmi" / "instance.rs").read_text()


def test_the_fmi_versions_are_siblings_over_one_core():
    """In the FMI layer, `fmi2` and `fmi3` are clients of the version-free core: neither imports
    the other or calls the other's functions, and the core (every module outside them but the
    build script, which renders both descriptions) imports neither and names no version's C types."""
    files = modules("fmi-export/src")
    edges = imports(files)
    versions = ("fmi2", "fmi3")

    def version_of(module):
        return next((v for v in versions if module == v or module.startswith(v + "::")), None)

    found = []
    for module, targets in edges.items():
        mine = version_of(module)
        for t in sorted(targets):
            theirs = version_of(t)
            if theirs and theirs != mine and module != "" and module != "build":
                found.append(f"{module} imports {t}")
        src = files[module]
        for other in versions:
            if other != mine and module not in ("", "build") and \
                    re.search(rf"\b{other}[A-Z]\w*\s*(::<[^>]*>)?\(", src):
                found.append(f"{module} calls an {other}* function")
        if mine is None and module not in ("", "build") and "fmi_sys" in src:
            found.append(f"{module} (core) uses fmi_sys")
    assert not found, "\n".join(found)
