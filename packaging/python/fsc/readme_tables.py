"""The README's parameter, input and output tables, generated from modelDescription.xml.

`python -m fsc.readme_tables` prints them (`--write`: into README.md); tests/test_readme.py checks that the README's
tables are exactly these, so documentation and FMU cannot disagree.
"""
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
XML = ROOT / "modelDescription" / "modelDescription.xml"
#: README heading of each table, by causality.
HEADINGS = {
    "parameter": "#### Parameters (fixed: set before fmi2ExitInitializationMode)",
    "calculatedParameter": "#### Calculated parameter",
    "input": "#### Inputs (continuous, settable at every communication point)",
    "output": "#### Outputs",
}


def tables(xml=XML) -> dict:
    """Markdown rows of each causality's table."""
    root = ET.parse(xml).getroot()
    # Switches: Integer types whose description names the items ("1 = rigid: ...; 2 = ancf: ...").
    switches = {t.get("name"): re.findall(r"(\d+) = (\w+)", t.get("description", ""))
                for t in root.find("TypeDefinitions")}
    rows = {c: [] for c in HEADINGS}
    for v in root.find("ModelVariables"):
        causality, kind = v.get("causality"), v[0]
        unit = kind.get("unit") or ""
        if kind.tag in ("Integer", "Boolean") and causality == "output":
            unit = kind.tag
        start = kind.get("start", "")
        description = v.get("description")
        if kind.get("declaredType") in switches:
            items = switches[kind.get("declaredType")]
            start = dict(items).get(start, start)
            allowed = ", ".join(f"{value}={name}" for value, name in items)
            description = description.rsplit(" (", 1)[0]
        elif kind.get("min") or kind.get("max"):
            allowed = f"[{kind.get('min', '')}, {kind.get('max', '')}]"
        else:
            allowed = ""
        description = description.replace("|", "\\|")
        name = v.get("name")
        if causality == "output":
            rows[causality].append(f"| `{name}` | {unit} | {description} |")
        else:
            rows[causality].append(f"| `{name}` | {unit} | {start} | {allowed} | {description} |")
    return rows


def readme_rows(readme: str, heading: str) -> list:
    """The table rows under `heading` in the README (without header and separator)."""
    lines = readme[readme.index(heading):].splitlines()[1:]
    table = []
    for line in lines:
        if line.startswith("|"):
            table.append(line)
        elif table:
            break
    return table[2:]


def write_readme(readme_path=ROOT / "README.md", xml=XML):
    """Replaces the rows of each table in the README by the generated ones."""
    readme = readme_path.read_text()
    for causality, rows in tables(xml).items():
        old = readme_rows(readme, HEADINGS[causality])
        start = readme.index("\n".join(old), readme.index(HEADINGS[causality]))
        readme = readme[:start] + "\n".join(rows) + readme[start + len("\n".join(old)):]
    readme_path.write_text(readme)


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        write_readme()
        sys.exit()
    for causality, rows in tables(sys.argv[1] if len(sys.argv) > 1 else XML).items():
        print(HEADINGS[causality])
        print("\n".join(rows))
        print()
