"""The README's Python section runs as written and shows the four areas of the package."""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"


def _python_blocks():
    return re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)


def test_readme_python_blocks_run(tmp_path, monkeypatch, capsys):
    blocks = _python_blocks()
    assert blocks, "the README has a Python section"
    code = "\n".join(blocks)
    # dry normal contact, frictional contact, rough surfaces, EHL
    for call in ("solve_normal(", "solve_tangential(", "roughness_parameters(", "solve_steady("):
        assert call in code, call
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "readme"}
    exec(compile(code, str(README), "exec"), namespace)  # noqa: S102 - the README's own code
    for name in ("res", "slip", "film"):
        assert namespace[name].converged, name
    assert "converged after" in capsys.readouterr().out
    assert (tmp_path / "line-out" / "report.html").is_file()
