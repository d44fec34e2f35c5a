"""The README's variable tables equal those generated from modelDescription.xml."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from readme_tables import HEADINGS, ROOT, readme_rows, tables  # noqa: E402


def test_readme_tables_match_the_model_description():
    readme = (ROOT / "README.md").read_text()
    for causality, rows in tables().items():
        assert readme_rows(readme, HEADINGS[causality]) == rows, (
            f"README table '{HEADINGS[causality]}' is stale: "
            "print the current one with python packaging/python/readme_tables.py")
