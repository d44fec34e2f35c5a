"""The README's variable tables equal those generated from modelDescription.xml, and its code runs."""
import re
import sys

from fsc.readme_tables import HEADINGS, ROOT, readme_rows, tables


def test_readme_tables_match_the_model_description():
    readme = (ROOT / "README.md").read_text()
    for causality, rows in tables().items():
        assert readme_rows(readme, HEADINGS[causality]) == rows, (
            f"README table '{HEADINGS[causality]}' is stale: "
            "print the current one with python packaging/python/readme_tables.py")


def test_readme_python_snippets_run():
    """Every Python block of the README runs as written, from the repository root (the README's
    Rust block is compiled and run by `cargo test --doc`)."""
    import subprocess

    readme = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) >= 3
    for block in blocks:
        result = subprocess.run([sys.executable, "-c", block], cwd=ROOT, capture_output=True,
                                text=True, timeout=300)
        assert result.returncode == 0, f"{block}\n{result.stderr[-2000:]}"
