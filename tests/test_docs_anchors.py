"""Every place the code cites docs/references.md names a section that exists there.

A report row reads "Moes (1992); docs/references.md#moes-line": the anchor is what a reader
follows, so a renamed heading or a new citation without its section would send them nowhere.
"""

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
REFERENCES = ROOT / "docs" / "references.md"


def _slug(heading: str) -> str:
    """GitHub's anchor of a Markdown heading: lower case, punctuation dropped, spaces to '-'."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def _anchors() -> set[str]:
    text = REFERENCES.read_text(encoding="utf-8")
    headings = re.findall(r"^#+\s+(.*)$", text, flags=re.M)
    return {_slug(h) for h in headings} | set(re.findall(r'<a (?:id|name)="([^"]+)"', text))


def _cited() -> dict[str, set[str]]:
    """anchor -> the source files citing it: cite(text, anchor) calls, literal links, and
    tables of ``(..., "Author (year)", "anchor")`` rows that are cited later."""
    cited: dict[str, set[str]] = {}
    for path in (ROOT / "src" / "asperity").rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            anchor = None
            if (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "cite"
                    and len(node.args) == 2 and isinstance(node.args[1], ast.Constant)):
                anchor = node.args[1].value
            elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                found = re.findall(r"references\.md#([\w-]+)", node.value)
                for name in found:
                    cited.setdefault(name, set()).add(path.name)
            elif (isinstance(node, ast.Tuple) and len(node.elts) >= 2  # (source, anchor) rows
                  and all(isinstance(e, ast.Constant) for e in node.elts[-2:])
                  and re.search(r"\((?:19|20)\d\d\)", str(node.elts[-2].value))
                  and re.fullmatch(r"[a-z0-9]+(?:-[a-z0-9]+)+", str(node.elts[-1].value))):
                anchor = node.elts[-1].value
            if isinstance(anchor, str):
                cited.setdefault(anchor, set()).add(path.name)
    return cited


def test_every_cited_reference_section_exists():
    cited = _cited()
    assert len(cited) >= 10, "the citations were not found"
    missing = {a: sorted(f) for a, f in cited.items() if a not in _anchors()}
    assert not missing, missing


def test_the_slug_rule_on_headings_of_the_file():
    """The anchors used across the reports, as GitHub renders their headings."""
    assert {"moes-line", "hamrock-dowson-point", "cattaneo-mindlin",
            "lubkin-torsion"} <= _anchors()
