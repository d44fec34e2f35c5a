"""The user guide's parameter, input and output tables, generated from modelDescription.xml.

`python -m fsc.variable_tables` prints them (`--write`: into docs/guide/variables.md); tests/test_docs.py
checks that the guide's tables are exactly these, and that every row the README quotes is one of them, so
documentation and FMU cannot disagree.
"""
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

#: The committed model description and the user guide's page of the variables, from a clone's root
#: (where `python -m fsc.variable_tables` runs).
XML = Path("modelDescription") / "modelDescription.xml"
GUIDE = Path("docs") / "guide" / "variables.md"
#: Heading of each table in the guide, by causality.
HEADINGS = {
    "parameter": "## Parameters (fixed: set before fmi2ExitInitializationMode)",
    "calculatedParameter": "## Calculated parameter",
    "input": "## Inputs (continuous, settable at every communication point)",
    "output": "## Outputs",
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


def rows_under(page: str, heading: str) -> list:
    """The table rows under `heading` in a Markdown page (without header and separator)."""
    lines = page[page.index(heading):].splitlines()[1:]
    table = []
    for line in lines:
        if line.startswith("|"):
            table.append(line)
        elif table:
            break
    return table[2:]


def write_guide(path=GUIDE, xml=XML):
    """Replaces the rows of each table in the guide's page by the generated ones."""
    page = path.read_text()
    for causality, rows in tables(xml).items():
        old = rows_under(page, HEADINGS[causality])
        start = page.index("\n".join(old), page.index(HEADINGS[causality]))
        page = page[:start] + "\n".join(rows) + page[start + len("\n".join(old)):]
    path.write_text(page)


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        write_guide()
        sys.exit()
    for causality, rows in tables(sys.argv[1] if len(sys.argv) > 1 else XML).items():
        print(HEADINGS[causality])
        print("\n".join(rows))
        print()
