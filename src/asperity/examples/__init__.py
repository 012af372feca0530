"""Built-in examples: one TOML case file per worked example of the seeds (and a few more).

Each file carries ``title``, ``description`` and ``source`` keys; ``long_running = true`` marks
full-size paper reproductions that take much longer than a minute.
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources

from ..errors import InputError

__all__ = ["DEFAULT_EXAMPLE", "Example", "example_text", "list_examples", "list_studies",
           "study_text"]

#: What ``asperity run`` runs when no case is given.
DEFAULT_EXAMPLE = "holmes-rough-CC"


@dataclass(frozen=True)
class Example:
    """One built-in example: its name, analysis, one-line description and source."""

    name: str
    analysis: str
    title: str
    description: str
    source: str
    long_running: bool


def _files(folder: str = ""):
    """The TOML files of the examples (``folder=""``) or of ``studies``, sorted by name."""
    root = resources.files(__name__)
    root = root / folder if folder else root
    return sorted((p for p in root.iterdir() if p.name.endswith(".toml")), key=lambda p: p.name)


def _text(name: str, folder: str, field: str, expected: str) -> str:
    for path in _files(folder):
        if path.name == f"{name}.toml":
            return path.read_text(encoding="utf-8")
    names = ", ".join(p.name.removesuffix(".toml") for p in _files(folder))
    raise InputError(field, f"{expected}{names}", name)


def list_examples() -> list[Example]:
    """All built-in examples, sorted by name."""
    from ..cases import parse_toml

    out = []
    for path in _files():
        data = parse_toml(path.read_text(encoding="utf-8"), path.name)
        out.append(Example(path.name.removesuffix(".toml"), data.get("analysis", "?"),
                           data.get("title", ""), data.get("description", ""),
                           data.get("source", ""), bool(data.get("long_running", False))))
    return out


def example_text(name: str) -> str:
    """The TOML text of a built-in example."""
    return _text(name, "", "example", "one of: ")


def list_studies() -> list[tuple[str, str]]:
    """Built-in parameter studies: (name, description) pairs."""
    from ..cases import parse_toml

    return [(p.name.removesuffix(".toml"),
             parse_toml(p.read_text(encoding="utf-8"), p.name).get("description", ""))
            for p in _files("studies")]


def study_text(name: str) -> str:
    """The TOML text of a built-in study."""
    return _text(name, "studies", "study", "a study file or one of: ")
