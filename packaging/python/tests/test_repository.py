"""The repository's texts describe the product, not how it was made (that is git's and
CHANGELOG.md's), and every link or cited file points inside the repository."""
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
TEXT = {".rs", ".py", ".md", ".sh", ".toml", ".xml", ".ssd", ".txt", ".c", ".yml", ".yaml", ""}
#: A reference to a tracker item or its numbered checks (a word followed by a number).
HISTORY = re.compile(r"\b(issue|acceptance) #?\d", re.IGNORECASE)
OUTSIDE = re.compile(r"\.\./shared|\b(MODEL|FMI|STYLE)\.md\b")
LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")


def texts():
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                           check=True).stdout.split()
    for name in files:
        path = ROOT / name
        if path.suffix in TEXT and path.is_file() and name != "CHANGELOG.md" \
                and not name.startswith("fuzz/corpus/") \
                and name != Path(__file__).relative_to(ROOT).as_posix():
            yield name, path.read_text(errors="replace")


def test_no_development_history_in_the_product_texts():
    found = [f"{name}:{n}: {line.strip()[:100]}" for name, text in texts()
             for n, line in enumerate(text.splitlines(), 1) if HISTORY.search(line)]
    assert not found, "\n".join(found)


def test_no_citation_or_link_points_outside_the_repository():
    found = [f"{name}:{n}: {line.strip()[:100]}" for name, text in texts()
             for n, line in enumerate(text.splitlines(), 1) if OUTSIDE.search(line)]
    for name, text in texts():
        if not name.endswith(".md"):
            continue
        for target in LINK.findall(text):
            if re.match(r"[a-z]+://", target):
                continue
            resolved = (ROOT / name).parent / target
            if not resolved.resolve().is_relative_to(ROOT) or not resolved.exists():
                found.append(f"{name}: link {target}")
    assert not found, "\n".join(found)
