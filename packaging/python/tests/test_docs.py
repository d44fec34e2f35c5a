"""The user guide's variable tables equal those generated from modelDescription.xml, the README
quotes only their rows, the README stays a front page, and the Python code of both runs."""
import re
import sys

from fsc.variable_tables import GUIDE, HEADINGS, XML, rows_under, tables

from conftest import ROOT


def test_guide_tables_match_the_model_description():
    page = (ROOT / GUIDE).read_text()
    for causality, rows in tables(ROOT / XML).items():
        assert rows_under(page, HEADINGS[causality]) == rows, (
            f"table '{HEADINGS[causality]}' of {GUIDE.name} is stale: "
            "rewrite it with python -m fsc.variable_tables --write")


def test_readme_quotes_the_generated_rows_and_is_a_front_page():
    readme = (ROOT / "README.md").read_text()
    generated = {row for rows in tables(ROOT / XML).values() for row in rows}
    quoted = [line for line in readme.splitlines() if line.startswith("| `")]
    assert len(quoted) >= 20
    assert [row for row in quoted if row not in generated] == []
    assert readme.count("\n") <= 350


def test_python_snippets_run():
    """Every Python block of the README and the user guide runs as written, from the repository root
    (the guide's Rust block is compiled and run by `cargo test --doc`)."""
    import subprocess

    pages = [ROOT / "README.md", *sorted((ROOT / "docs" / "guide").glob("*.md"))]
    blocks = [block for page in pages
              for block in re.findall(r"```python\n(.*?)```", page.read_text(), re.S)]
    assert len(blocks) >= 5
    for block in blocks:
        result = subprocess.run([sys.executable, "-c", block], cwd=ROOT, capture_output=True,
                                text=True, timeout=300)
        assert result.returncode == 0, f"{block}\n{result.stderr[-2000:]}"
