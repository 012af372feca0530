"""Atomic writes: the target appears whole or not at all, and an interrupt waits for it."""

import os
import signal

import pytest

from asperity.atomic import atomic_path


class Stop(Exception):
    pass


@pytest.fixture
def raising_sigint():
    def handler(signum, _frame):
        raise Stop(signum)

    previous = signal.signal(signal.SIGINT, handler)
    yield
    signal.signal(signal.SIGINT, previous)


def test_failed_block_leaves_the_previous_file(tmp_path):
    target = tmp_path / "result.nc"
    target.write_text("old")
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text("half")
        raise RuntimeError("killed while writing")
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["result.nc"]


def test_interrupt_while_writing_is_delivered_after_the_file_is_in_place(tmp_path,
                                                                         raising_sigint):
    """A SIGINT in the middle of a write (as in the CI failure where h5netcdf's handle was left
    half closed) is raised only once the new file has replaced the old one."""
    target = tmp_path / "result.nc"
    target.write_text("old")
    written = []
    with pytest.raises(Stop), atomic_path(target) as tmp:
        tmp.write_text("first half ")
        os.kill(os.getpid(), signal.SIGINT)
        with tmp.open("a") as f:
            f.write("second half")
        written.append(True)
    assert written == [True]
    assert target.read_text() == "first half second half"


def test_handlers_are_restored_after_a_quiet_write(tmp_path, raising_sigint):
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    with atomic_path(tmp_path / "a.txt") as tmp:
        tmp.write_text("x")
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before
    with pytest.raises(Stop):
        os.kill(os.getpid(), signal.SIGINT)
        signal.getsignal(signal.SIGINT)  # a bytecode boundary for the handler to run
