"""Binning a large map before ``surface stats`` (``--bin``), and the warning on a large map.

References: a k x k block's mean by explicit loops; the law of total variance (the variance of
the heights is that of the block means plus the mean variance within the blocks), so that the
Sq the note gives, sqrt(Sq_binned^2 + W^2), is the unbinned map's when only the mean is removed.
"""

import json
import math

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from asperity.cli.surface import surface_app
from asperity.errors import InputError
from asperity.surfaces import Topography, evaluate_texture, gaussian_topography
from asperity.surfaces.binning import LARGE_MAP, bin_surface, large_map

app = typer.Typer()
app.add_typer(surface_app, name="surface")


def rough_map(n=96, m=80):
    t = gaussian_topography((n * 1e-6, m * 1e-6), 1e-6, 0.2e-6, 3e-6, seed=4)
    return Topography(t.x, t.y, t.z)


def test_blocks_are_averaged_and_the_note_gives_the_height_lost():
    t = rough_map(97, 80)  # 97 is not a multiple of 4: the last point is dropped
    binned, _, note = bin_surface(t, 4)
    assert binned.shape == (24, 20)
    for i, j in ((0, 0), (5, 7), (23, 19)):
        block = [t.z[4 * i + a, 4 * j + b] for a in range(4) for b in range(4)]
        assert binned.z[i, j] == pytest.approx(sum(block) / 16, rel=1e-12)
    assert binned.x[0] == pytest.approx(np.mean(t.x[:4])) and binned.spacing[0] == pytest.approx(
        4e-6)
    within = float(note.split(", rms ")[1].split(" um")[0]) * 1e-6
    whole = evaluate_texture(Topography(t.x[:96], t.y, t.z[:96]), form_degree=0)
    coarse = evaluate_texture(binned, form_degree=0)
    sq, sq_binned = whole.groups["height"]["Sq"], coarse.groups["height"]["Sq"]
    assert math.hypot(sq_binned, within) == pytest.approx(sq, rel=2e-4)  # 4 digits printed
    assert sq_binned < 0.95 * sq and note.startswith("binned 4 x 4 (--bin 4): 97 x 80 points")


def test_a_block_mostly_missing_is_masked():
    t = rough_map(16, 16)
    mask = np.zeros(t.shape, bool)
    mask[:2, :2] = True  # the whole first 2 x 2 block
    mask[2, 2] = True  # one of four: kept
    _, binned_mask, _ = bin_surface(t, 2, mask)
    assert binned_mask[0, 0] and binned_mask.sum() == 1


def test_bin_is_refused_when_too_little_remains():
    with pytest.raises(InputError, match="--bin: expected a block of at most 10 points"):
        bin_surface(rough_map(), 12)


def test_large_map_warns_with_the_bin_that_fits():
    assert large_map(LARGE_MAP) is None
    warning = large_map(4096 * 4096)
    assert warning.startswith("large map: 16.8 M points (limit 4.19 M)")
    assert "--bin 2 averages 2 x 2 blocks (4.19 M points)" in warning


def test_stats_bins_and_says_so(tmp_path, monkeypatch):
    t = rough_map()
    path = tmp_path / "m.npz"
    np.savez(path, x=t.x, y=t.y, z=t.z)
    runner = CliRunner()
    res = runner.invoke(app, ["surface", "stats", str(path), "--bin", "2", "--json"])
    assert res.exit_code == 0, res.output
    out = json.loads(res.stdout)
    assert out["points"] == [48, 40] and out["spacing_m"] == pytest.approx([2e-6, 2e-6])
    assert any(n.startswith("binned 2 x 2") for n in out["notes"])
    monkeypatch.setattr("asperity.surfaces.binning.available_memory", lambda: 1e5)
    res = runner.invoke(app, ["surface", "stats", str(path)])
    assert res.exit_code == 2
    assert res.output.strip().splitlines()[-1].startswith("error: --bin: expected a block size")
