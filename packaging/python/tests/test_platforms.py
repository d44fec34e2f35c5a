"""Tests of the release FMU's binaries (packaging/release.sh): the archive, the linux64 glibc
baseline, the win64 DLL under wine and the darwin64 universal binary, and bit-identical results on
every platform that runs here.

Every run is benchmark B's DefaultExperiment (24 ms in 240 communication steps of 1e-4 s) through
the portable C master packaging/master/fmu_run.c, which writes every Real output at every
communication point as its 64 bits in hexadecimal, so that two runs compare bit for bit.
"""
import os
import re
import shutil
import struct
import subprocess
from pathlib import Path

import pytest
from fmpy import read_model_description, supported_platforms
from fmpy.validation import validate_fmu

ROOT = Path(__file__).resolve().parents[3]
RELEASE_FMU = ROOT / "target" / "fmu" / "release" / "FlexibleSliderCrank.fmu"
BINARIES = ROOT / "target" / "cross" / "binaries"
# This machine's own build of the library: the development profile's, which the Rust tests share.
HOST_LIBRARY = ROOT / "target" / "debug" / "libflexible_slider_crank.so"
WORK = ROOT / "target" / "platform-tests"
MASTER = ROOT / "packaging" / "master"
# The oldest Debian release the package mirrors still serve: glibc 2.31, older than this machine's.
OLD_DEBIAN = "bullseye"
FMI2_FUNCTIONS = 34
# Every function of the FMI 3.0 headers (those of capabilities the FMU lacks refuse their calls).
FMI3_FUNCTIONS = 75
SAVE_AT = 120



@pytest.fixture(scope="module")
def release():
    """The release FMU's model description, read when a test needs it (a missing release build
    fails that test, not the collection of every test), its GUID and the C master's experiment:
    24 ms in 1e-4 s steps, recording every Real output."""
    md = read_model_description(str(RELEASE_FMU))
    outputs = [v for v in md.modelVariables if v.causality == "output" and v.type == "Real"]
    experiment = ["0.024", "1e-4", ",".join(str(v.valueReference) for v in outputs)]
    return md.guid, experiment, [v.name for v in outputs]


@pytest.fixture(scope="module")
def fmi3_token():
    """The instantiation token of the release FMI 3.0 slider-crank (with its arrays), which the
    library's fmi3* functions check."""
    return read_model_description(str(RELEASE_FMU.parent / "fmi3" / RELEASE_FMU.name)).guid


def run(args, **kwargs):
    """Runs a command; a failure reports its exit status and what it printed."""
    done = subprocess.run(args, capture_output=True, text=True, **kwargs)
    if done.returncode != 0:
        pytest.fail(f"{' '.join(map(str, args))} exited with status {done.returncode}\n"
                    f"stdout:\n{done.stdout[-4000:]}\nstderr:\n{done.stderr[-4000:]}",
                    pytrace=False)
    return done


@pytest.fixture(scope="module")
def work():
    WORK.mkdir(parents=True, exist_ok=True)
    return WORK


@pytest.fixture(scope="module")
def linux_run(work, release):
    """The release linux64 binary's run, and the FMU state it serialized at point SAVE_AT."""
    master = work / "fmu_run"
    run(["gcc", "-O2", "-Wall", "-Werror", str(MASTER / "fmu_run.c"), "-o", str(master), "-ldl"])
    out, state = work / "linux64.txt", work / "linux64.state"
    guid, experiment, _ = release
    run([str(master), str(BINARIES / "linux64" / "FlexibleSliderCrank.so"), guid, *experiment,
         str(out), "--save-at", str(SAVE_AT), str(state)])
    return out.read_text(), state


def lines_differing(a, b):
    a, b = a.splitlines(), b.splitlines()
    assert len(a) == len(b), (len(a), len(b))
    return [i for i, (x, y) in enumerate(zip(a, b)) if x != y]


MODELS = ["FlexibleSliderCrank", "DcMotor", "LubricationCircuit"]


@pytest.mark.parametrize("model", MODELS)
def test_release_fmi3_fmu_validates_holds_every_platform_and_equals_fmi2(model):
    """The release FMI 3.0 FMU carries the same libraries in FMI 3's platform folders (the macOS
    universal binary's slices in their architectures' folders) and, on this machine, runs its
    DefaultExperiment through fmpy bit for bit as the release FMI 2.0 FMU does."""
    from fmpy import simulate_fmu
    import numpy as np

    import zipfile

    fmu3 = str(RELEASE_FMU.parent / "fmi3" / f"{model}.fmu")
    assert validate_fmu(fmu3) == []
    with zipfile.ZipFile(fmu3) as z:
        names = set(z.namelist())
    for platform, ext in [("x86_64-linux", "so"), ("aarch64-linux", "so"),
                          ("x86_64-windows", "dll"), ("x86_64-darwin", "dylib"),
                          ("aarch64-darwin", "dylib")]:
        assert f"binaries/{platform}/{model}.{ext}" in names, sorted(names)
    r2 = simulate_fmu(str(RELEASE_FMU.parent / f"{model}.fmu"))
    r3 = simulate_fmu(fmu3)
    for name in r2.dtype.names:
        assert np.array_equal(r2[name], r3[name]), name


@pytest.mark.parametrize("model", MODELS)
def test_fmi3_darwin_folders_hold_the_universal_binarys_slices(model, tmp_path):
    """FMI 3.0 names each macOS architecture: x86_64-darwin and aarch64-darwin hold one slice each,
    byte for byte the slice of the universal binary the FMI 2.0 FMU ships in darwin64."""
    import zipfile

    universal = BINARIES / "darwin64" / f"{model}.dylib"
    with zipfile.ZipFile(RELEASE_FMU.parent / "fmi3" / f"{model}.fmu") as z:
        for folder, arch in [("x86_64-darwin", "x86_64"), ("aarch64-darwin", "arm64")]:
            shipped = tmp_path / f"{folder}.dylib"
            shipped.write_bytes(z.read(f"binaries/{folder}/{model}.dylib"))
            assert run(["llvm-lipo-14", "-archs", str(shipped)]).stdout.split() == [arch]
            thin = tmp_path / f"{arch}.dylib"
            run(["llvm-lipo-14", str(universal), "-thin", arch, "-output", str(thin)])
            assert shipped.read_bytes() == thin.read_bytes(), folder


@pytest.mark.parametrize("model", MODELS)
def test_release_fmu_validates_and_holds_every_platform(model):
    fmu = str(RELEASE_FMU.parent / f"{model}.fmu")
    assert validate_fmu(fmu) == []
    platforms = supported_platforms(fmu)
    for platform in ["linux64", "win64", "darwin64"]:
        assert platform in platforms, platforms


def test_release_systems_hold_the_release_fmus():
    """Each release SSP and OSP folder carries its release FMUs (every platform), byte for byte."""
    import zipfile

    for name, folder, models in [("MotorCrank", "motor-crank", ["FlexibleSliderCrank", "DcMotor"]),
                                 ("LubeCrank", "lube-crank",
                                  ["FlexibleSliderCrank", "LubricationCircuit"])]:
        with zipfile.ZipFile(RELEASE_FMU.parent / f"{name}.ssp") as ssp:
            for model in models:
                fmu = (RELEASE_FMU.parent / f"{model}.fmu").read_bytes()
                assert ssp.read(f"resources/{model}.fmu") == fmu
                assert (RELEASE_FMU.parent / folder / f"{model}.fmu").read_bytes() == fmu


@pytest.mark.parametrize("model", MODELS)
def test_linux64_needs_glibc_2_28_at_most(model):
    symbols = run(["objdump", "-T", str(BINARIES / "linux64" / f"{model}.so")]).stdout
    versions = {tuple(int(x) for x in v.split(".")) for v in re.findall(r"GLIBC_([0-9.]+)", symbols)}
    assert versions and max(versions) <= (2, 28), sorted(versions)
    assert len(set(re.findall(r"\bfmi2\w+", symbols))) == FMI2_FUNCTIONS
    assert len(set(re.findall(r"\bfmi3\w+", symbols))) == FMI3_FUNCTIONS


def test_linux64_equals_the_host_build(linux_run, work, release):
    """The release linux64 binary (zig's linker, glibc 2.28's symbols, the release profile) and
    this machine's development build give the same outputs to the bit."""
    guid, experiment, _ = release
    # (built with the workspace's test programs, as the test command and the Rust tests build it:
    # alone, it would be compiled with other features of the crates under it, a second time)
    run(["cargo", "build", "--quiet", "--workspace", "--lib", "--tests"], cwd=ROOT)
    out = work / "host.txt"
    run([str(work / "fmu_run"), str(HOST_LIBRARY), guid, *experiment, str(out)])
    assert lines_differing(out.read_text(), linux_run[0]) == []


def test_the_reference_results_in_the_release_fmu_are_its_linux64_run(linux_run, release):
    """The reference results the release FMU carries (extra/org.fmi-standard.fmi-ls-ref/) are the
    release linux64 binary's DefaultExperiment at every communication point, to the bit; the win64
    run equals that one (below), so the reference holds for it too."""
    import struct
    import zipfile

    with zipfile.ZipFile(RELEASE_FMU) as fmu:
        lines = fmu.read("extra/org.fmi-standard.fmi-ls-ref/FlexibleSliderCrank_ref.csv")
    header, *rows = lines.decode().splitlines()
    names = [n.strip('"') for n in header.split(",")[1:]]
    assert names == release[2]
    def bits(x):
        return struct.pack(">d", float(x)).hex()
    expected = [" ".join([str(k)] + [bits(x) for x in row.split(",")[1:]])
                for k, row in enumerate(rows)]
    assert lines_differing("\n".join(expected) + "\n", linux_run[0]) == []


@pytest.mark.skipif(os.geteuid() != 0, reason="debootstrap and chroot need root")
def test_linux64_runs_on_an_older_debian_bit_identically(linux_run, work, release):
    guid, experiment, _ = release
    root = work / OLD_DEBIAN
    if not (root / "usr" / "bin" / "ldd").exists():
        shutil.rmtree(root, ignore_errors=True)
        run(["debootstrap", "--variant=minbase", OLD_DEBIAN, str(root),
             "http://deb.debian.org/debian"])
    glibc = run(["chroot", str(root), "ldd", "--version"]).stdout.splitlines()[0]
    assert glibc.endswith("2.31"), glibc
    zig = Path(run([str(ROOT / ".venv" / "bin" / "python"), "-c",
                    "import ziglang, os; print(os.path.dirname(ziglang.__file__))"]).stdout.strip())
    run([str(zig / "zig"), "cc", "-target", "x86_64-linux-gnu.2.28", "-O2",
         str(MASTER / "fmu_run.c"), "-o", str(root / "fmu_run")])
    shutil.copy(BINARIES / "linux64" / "FlexibleSliderCrank.so", root / "FlexibleSliderCrank.so")
    run(["chroot", str(root), "/fmu_run", "/FlexibleSliderCrank.so", guid, *experiment, "/out.txt"])
    assert lines_differing((root / "out.txt").read_text(), linux_run[0]) == []


@pytest.fixture(scope="module")
def wine(work, release):
    """A directory with the win64 DLL, the C master built for Windows and the test-only
    bcryptprimitives.dll that wine 8 lacks; and a function running the master there under wine."""
    win = work / "win64"
    win.mkdir(exist_ok=True)
    gcc = "x86_64-w64-mingw32-gcc"
    run([gcc, "-O2", "-Wall", "-Werror", str(MASTER / "fmu_run.c"), "-o", str(win / "fmu_run.exe")])
    run([gcc, "-O2", "-shared", str(MASTER / "bcryptprimitives.c"), "-ladvapi32",
         "-o", str(win / "bcryptprimitives.dll")])
    shutil.copy(BINARIES / "win64" / "FlexibleSliderCrank.dll", win / "FlexibleSliderCrank.dll")
    env = dict(os.environ, WINEPREFIX=str(work / "wineprefix"), WINEDEBUG="-all")
    # Create the prefix and wait until wine has finished setting it up, so that no run of the
    # master overlaps the prefix's first-time update.
    run(["wineboot", "--init"], env=env)
    run(["wineserver", "--wait"], env=env)

    def master(*args):
        guid, experiment, _ = release
        return run(["wine", "fmu_run.exe", "FlexibleSliderCrank.dll", guid, *experiment, *args],
                   cwd=win, env=env)
    return win, master


def test_win64_under_wine_equals_linux64_at_every_communication_point(linux_run, wine):
    win, master = wine
    master("win64.txt")
    assert lines_differing((win / "win64.txt").read_text(), linux_run[0]) == []


def zig():
    """The zig compiler of the venv (PyPI ziglang)."""
    return Path(run([str(ROOT / ".venv" / "bin" / "python"), "-c",
                     "import ziglang, os; print(os.path.dirname(ziglang.__file__))"]
                    ).stdout.strip()) / "zig"


@pytest.fixture(scope="module")
def aarch64_master(work, release, fmi3_token):
    """The C master built for ARM64 Linux (glibc 2.28), and a function running it on the
    aarch64-linux library under qemu-user with Debian's ARM64 C library (libc6-arm64-cross)."""
    master = work / "fmu_run_aarch64"
    run([str(zig()), "cc", "-target", "aarch64-linux-gnu.2.28", "-O2", "-Wall", "-Werror",
         str(MASTER / "fmu_run.c"), "-o", str(master), "-ldl"])

    def master_run(*args):
        guid, experiment, _ = release
        identity = fmi3_token if "--fmi3" in args else guid
        return run(["qemu-aarch64", "-L", "/usr/aarch64-linux-gnu", str(master),
                    str(BINARIES / "aarch64-linux" / "FlexibleSliderCrank.so"), identity,
                    *experiment, *args])
    return master_run


def test_aarch64_linux_under_qemu_starts_as_linux64_to_round_off(linux_run, aarch64_master, work,
                                                                   release):
    """The ARM64 Linux library, run by the C master under qemu-user (its fmi2 functions: the same
    library serves the FMI 3 FMU), completes the experiment and starts where the x86_64 Linux one
    does, to the round-off of the linear algebra: faer's kernels take each processor's own vector
    instructions (NEON there, AVX2 with FMA here), so the reduced rod differs in the last bits
    (measured: 2.6e-11 of each output's range at t = 0). A dry-clearance run is chaotic: from the
    first impacts such differences grow, as any perturbation does (the largest joint-force peak
    of the run: 0.013 % apart), so the runs are not compared point by point after the start."""
    out = work / "aarch64-linux.txt"
    aarch64_master(str(out))
    arm, x86 = (
        [[struct.unpack(">d", bytes.fromhex(h))[0] for h in line.split()[1:]]
         for line in text.splitlines()]
        for text in (out.read_text(), linux_run[0]))
    assert len(arm) == len(x86) == 241
    ranges = [max(abs(row[i]) for row in x86) for i in range(len(x86[0]))]
    start = max(abs(a - b) / r for a, b, r in zip(arm[0], x86[0], ranges) if r > 0)
    assert start < 1e-9, start
    force = release[2].index("joint.forcePeak")
    peak_arm, peak_x86 = (max(row[force] for row in run) for run in (arm, x86))
    assert abs(peak_arm - peak_x86) < 0.01 * peak_x86, (peak_arm, peak_x86)


def test_the_c_master_through_fmi3_equals_fmi2_on_linux64(linux_run, work, release, fmi3_token):
    """The C master through the library's fmi3* functions (fmi3InstantiateCoSimulation,
    fmi3GetFloat64, fmi3DoStep, the FMU state) gives the FMI 2 run's bits at every communication
    point, and a state serialized through fmi2 continues through fmi3 bit for bit (one format)."""
    _, experiment, _ = release
    library = str(BINARIES / "linux64" / "FlexibleSliderCrank.so")
    out = work / "linux64-fmi3.txt"
    run([str(work / "fmu_run"), library, fmi3_token, *experiment, str(out), "--fmi3"])
    assert lines_differing(out.read_text(), linux_run[0]) == []
    resumed = work / "linux64-fmi3-resumed.txt"
    run([str(work / "fmu_run"), library, fmi3_token, *experiment, str(resumed), "--restore-at",
         str(SAVE_AT), str(linux_run[1]), "--fmi3"])
    assert resumed.read_text().splitlines() == linux_run[0].splitlines()[SAVE_AT:]


def test_aarch64_linux_under_qemu_through_fmi3_equals_its_fmi2_run(aarch64_master, work):
    """On ARM64 too, the C master through the fmi3* functions gives the fmi2 functions' bits."""
    fmi2, fmi3 = work / "aarch64-fmi2.txt", work / "aarch64-fmi3.txt"
    aarch64_master(str(fmi2))
    aarch64_master(str(fmi3), "--fmi3")
    assert lines_differing(fmi3.read_text(), fmi2.read_text()) == []


def test_aarch64_linux_exports_both_versions_against_glibc_2_28():
    for model in MODELS:
        library = str(BINARIES / "aarch64-linux" / f"{model}.so")
        symbols = run(["llvm-objdump-14", "-f", "-T", library]).stdout
        assert "file format elf64-littleaarch64" in symbols
        versions = {tuple(int(x) for x in v.split("."))
                    for v in re.findall(r"GLIBC_([0-9.]+)", symbols)}
        assert versions and max(versions) <= (2, 28), sorted(versions)
        assert len(set(re.findall(r"\bfmi2\w+", symbols))) == FMI2_FUNCTIONS
        assert len(set(re.findall(r"\bfmi3\w+", symbols))) == FMI3_FUNCTIONS


def test_state_saved_on_linux64_continues_bit_identically_on_win64(linux_run, wine):
    win, master = wine
    shutil.copy(linux_run[1], win / "linux64.state")
    master("continued.txt", "--restore-at", str(SAVE_AT), "linux64.state")
    continued = (win / "continued.txt").read_text()
    assert lines_differing(continued, "".join(linux_run[0].splitlines(True)[SAVE_AT:])) == []


@pytest.mark.parametrize("model", MODELS)
def test_win64_exports_fmi2_and_imports_system_dlls_only(model):
    headers = run(["x86_64-w64-mingw32-objdump", "-p",
                   str(BINARIES / "win64" / f"{model}.dll")]).stdout
    assert len(set(re.findall(r"\]\s+(fmi2\w+)", headers))) == FMI2_FUNCTIONS
    assert len(set(re.findall(r"\]\s+(fmi3\w+)", headers))) == FMI3_FUNCTIONS
    imports = {name.lower() for name in re.findall(r"DLL Name: (\S+)", headers)}
    system = {"kernel32.dll", "ntdll.dll", "msvcrt.dll", "userenv.dll", "ws2_32.dll",
              "bcryptprimitives.dll", "advapi32.dll", "api-ms-win-core-synch-l1-2-0.dll"}
    assert imports <= system, imports - system


def test_win64_carries_no_code_the_other_platforms_drop():
    """The slider-crank's DLL is 1.3x the size of its linux64 library (5.4 MB against 4.1 MB);
    it was 2.9x (12.1 MB) when mingw-w64's link kept faer's unused single-precision and complex
    kernels, compiled without optimization, that the other platforms' links drop."""
    dll = (BINARIES / "win64" / "FlexibleSliderCrank.dll").stat().st_size
    so = (BINARIES / "linux64" / "FlexibleSliderCrank.so").stat().st_size
    assert dll < 2 * so, f"win64 {dll} bytes against linux64 {so}"


@pytest.mark.parametrize("model", MODELS)
def test_darwin64_is_universal_for_macos_11_with_the_fmi2_exports(model):
    dylib = str(BINARIES / "darwin64" / f"{model}.dylib")
    assert run(["llvm-lipo-14", "-archs", dylib]).stdout.split() == ["x86_64", "arm64"]
    for arch in ["x86_64", "arm64"]:
        headers = run(["llvm-objdump-14", "--macho", f"--arch={arch}", "--private-headers",
                       dylib]).stdout
        assert re.search(r"cmd LC_BUILD_VERSION.*?platform macos.*?minos 11\.0", headers, re.S)
        if arch == "arm64":
            assert "LC_CODE_SIGNATURE" in headers
        assert re.search(rf"cmd LC_ID_DYLIB.*?name @rpath/{model}\.dylib", headers, re.S)
        exports = run(["llvm-nm-14", f"--arch={arch}", "-gU", dylib]).stdout
        assert len(set(re.findall(r"\b_(fmi2\w+)", exports))) == FMI2_FUNCTIONS
        assert len(set(re.findall(r"\b_(fmi3\w+)", exports))) == FMI3_FUNCTIONS
