"""The command says once, on stderr, when numba compiles an engine (a first run)."""

from __future__ import annotations

import numba as nb

from freestand.cli.common import COMPILE_NOTICE, compile_notice


@nb.njit
def _twice(x):
    return 2.0 * x


@nb.njit
def _thrice(x):
    return 3.0 * _twice(x)


def test_a_compilation_is_announced_once_on_stderr(capsys):
    with compile_notice():
        assert _thrice(1.0) == 6.0  # two functions compiled, one nested in the other
    captured = capsys.readouterr()
    assert captured.err.count(COMPILE_NOTICE) == 1
    assert captured.out == ""  # stdout may hold a JSON document


def test_a_compiled_function_is_not_announced(capsys):
    assert _twice(2.0) == 4.0  # compiled here, outside the notice
    with compile_notice():
        assert _twice(3.0) == 6.0
    assert capsys.readouterr().err == ""
