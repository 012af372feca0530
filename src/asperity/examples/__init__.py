"""Built-in examples: one TOML case file per worked example of the seeds (and a few more).

Each file carries ``title``, ``description`` and ``source`` keys; ``long_running = true`` marks
full-size paper reproductions that take much longer than a minute.

``asperity example NAME`` prints a built-in example or, where no example has the name, a
built-in study (:func:`builtin_text`), to copy and edit.

Data shipped with the examples (``data/``) is named in case files as ``builtin:NAME``
(``path = "builtin:ground-profile.csv"``), which resolves wherever the case file is;
:func:`write_example` writes an example with its data beside it, the path made relative.
"""

from __future__ import annotations

import difflib
import shutil
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from ..errors import InputError

__all__ = ["BUILTIN_PREFIX", "DEFAULT_EXAMPLE", "Example", "builtin_data", "builtin_text",
           "example_text", "list_examples", "list_studies", "study_text", "write_example"]

#: Prefix of the names of data files shipped with asperity (``builtin:ground-profile.csv``).
BUILTIN_PREFIX = "builtin:"

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


def _find(name: str, folder: str) -> str | None:
    """The TOML text of ``NAME.toml`` among the examples (``folder=""``) or the studies."""
    for path in _files(folder):
        if path.name == f"{name}.toml":
            return path.read_text(encoding="utf-8")
    return None


def _names(folder: str) -> list[str]:
    """The names of the built-in examples (``folder=""``) or studies."""
    return [p.name.removesuffix(".toml") for p in _files(folder)]


def _missing(name: str, field: str, names: list[str], expected: str, kind: str = ""):
    """Raise the :class:`InputError` of a name that is none of ``names``: the name meant where
    one reads like it, else ``expected``; ``kind`` names what was looked for (``field``)."""
    kind = kind or field
    listed = "asperity examples lists them"
    if Path(name).is_dir():
        raise InputError(field, "", problem=f"{name} is a folder; give a .toml file in it or "
                                            f"the name of a built-in {kind} ({listed})")
    by_lower = {n.lower(): n for n in names}
    close = ([name.lower()] if name.lower() in by_lower else
             difflib.get_close_matches(name.lower(), list(by_lower), n=3, cutoff=0.75))
    if close:
        meant = " or ".join(by_lower[n] for n in close)
        raise InputError(field, "", problem=f"no built-in {kind} {name!r}; did you mean "
                                            f"{meant}? ({listed})")
    raise InputError(field, expected, name)


def _text(name: str, folder: str, field: str, expected: str) -> str:
    text = _find(name, folder)
    if text is None:
        names = _names(folder)
        _missing(name, field, names, f"{expected}{', '.join(names)}")
    return text


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


def builtin_text(name: str) -> tuple[str, str]:
    """The kind (``"example"`` or ``"study"``) and TOML text of a built-in example or, where
    no example has the name, a built-in study (what ``asperity example NAME`` prints).

    Raises
    ------
    InputError
        ``example``: for a name of neither, with the names that read like it or all of them.
    """
    for folder, kind in (("", "example"), ("studies", "study")):
        text = _find(name, folder)
        if text is not None:
            return kind, text
    examples, studies = _names(""), _names("studies")
    _missing(name, "example", examples + studies, f"an example ({', '.join(examples)}) or a "
             f"study ({', '.join(studies)})", kind="example or study")


def list_studies() -> list[tuple[str, str]]:
    """Built-in parameter studies: (name, description) pairs."""
    from ..cases import parse_toml

    return [(p.name.removesuffix(".toml"),
             parse_toml(p.read_text(encoding="utf-8"), p.name).get("description", ""))
            for p in _files("studies")]


def study_text(name: str) -> str:
    """The TOML text of a built-in study."""
    return _text(name, "studies", "study", "a study file or one of: ")


def builtin_data(name: str) -> Path:
    """The path of a shipped data file named ``builtin:NAME`` or ``NAME``."""
    name = name.removeprefix(BUILTIN_PREFIX)
    folder = resources.files(__name__) / "data"
    for item in folder.iterdir():
        if item.name == name:
            return Path(str(item))
    names = ", ".join(sorted(BUILTIN_PREFIX + p.name for p in folder.iterdir()
                             if not p.name.startswith((".", "_"))))
    raise InputError("path", f"one of the shipped data files: {names}", name)


def write_example(name: str, folder) -> list[Path]:
    """Write example (or study) ``name`` to ``folder/NAME.toml`` with the shipped data it
    names beside it.

    Every ``"builtin:FILE"`` in the case becomes ``"FILE"``, which a case file resolves relative
    to its own folder, and FILE is copied there. A built-in study names its base by the
    built-in example's name, which ``asperity sweep`` finds from any folder. Returns the paths
    written, the case first.
    """
    _, text = builtin_text(name)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    written = [folder / f"{name}.toml"]
    for token in sorted(set(text.split('"'))):
        if token.startswith(BUILTIN_PREFIX):
            source = builtin_data(token)
            written.append(Path(shutil.copyfile(source, folder / source.name)))
            text = text.replace(f'"{token}"', f'"{source.name}"')
    written[0].write_text(text, encoding="utf-8")
    return written
