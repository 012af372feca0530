"""The validation table's checks, run as tests: every row within its tolerance."""

import pytest

from asperity.validation import CHECKS


def _param(check):
    marks = [pytest.mark.slow] if check.slow else []
    return pytest.param(check, id=check.name, marks=marks)


@pytest.mark.parametrize("check", [_param(c) for c in CHECKS])
def test_check_passes(check):
    rows = check.function()
    assert rows, "a check must compare at least one number"
    for row in rows:
        if row.tolerance is not None:
            assert abs(row.relative_error) <= row.tolerance, (
                f"{check.name}: {row.quantity} = {row.value:.6g}, reference {row.reference:.6g} "
                f"({row.source}), error {row.relative_error:+.2e} > {row.tolerance:.1e}")


def test_validate_command_prints_the_table():
    from typer.testing import CliRunner

    from asperity.cli import app

    result = CliRunner().invoke(app, ["validate", "--json", "-k", "hertz"])
    assert result.exit_code == 0, result.output
    assert '"passed": true' in result.output
