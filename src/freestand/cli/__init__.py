"""The ``freestand`` command: a thin layer over the library.

Each sub-command lives in its own module and only parses arguments, calls the
library and prints or writes results. Input problems surface as
:class:`freestand.errors.FreestandError`; :func:`main` prints their message and
exits with status 2, never with a traceback.
"""

from __future__ import annotations

import sys

import typer

from freestand.errors import FreestandError

app = typer.Typer(
    name="freestand",
    help="Seismic screening of free-standing equipment modelled as stacks of rigid blocks.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    # Plain help: rich markup would eat every "[s]", "[m]" or "[beam]" of the help texts,
    # and the rich help shows flags as "<bool>".
    rich_markup_mode=None,
)


def _version(value: bool) -> None:
    if value:
        from freestand import __version__

        typer.echo(f"freestand {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(
        False,
        "--version",
        callback=_version,
        is_eager=True,
        help="Print the version of freestand and exit.",
    ),
) -> None:
    """Seismic screening of free-standing equipment modelled as stacks of rigid blocks.

    Bare numbers are SI units; options that take a quantity also accept a unit,
    e.g. --peak 0.3g or --peak "2.9 m/s^2".
    """


def _register() -> None:
    from freestand.cli import (
        fragility,
        frequency,
        maps,
        overturn,
        records,
        report,
        screen,
        simulate,
    )

    screen.register(app)
    frequency.register(app)
    maps.register(app)
    overturn.register(app)
    simulate.register(app)
    report.register(app)
    records.register(app)
    fragility.register(app)


_register()


def _print_error(message: str) -> None:
    from rich.console import Console
    from rich.markup import escape

    Console(emoji=False, stderr=True, highlight=False, soft_wrap=True).print(
        f"[bold red]error:[/] {escape(message)}", markup=True
    )


def _is_usage_error(error: BaseException) -> bool:
    """A click/typer usage error (typer may vendor click, so no import of click here)."""
    return callable(getattr(error, "show", None)) and isinstance(
        getattr(error, "exit_code", None), int
    )


def _given_value(error: BaseException, args: list[str]) -> str | None:
    """The value typed for the option a usage error is about, if it can be found."""
    param = getattr(error, "param", None)
    names = list(getattr(param, "opts", ()) or ()) + list(getattr(param, "secondary_opts", ()))
    for k, arg in enumerate(args):
        for name in names:
            if not name.startswith("-"):
                continue
            if arg == name and k + 1 < len(args):
                return args[k + 1]
            if arg.startswith(name + "="):
                return arg[len(name) + 1 :]
    return None


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status.

    Usage mistakes (unknown command or option, a value that is not a number)
    print typer's short usage message and return 2; a
    :class:`~freestand.errors.FreestandError` prints its message and returns 2;
    a computation that fails returns 1. No traceback reaches the user: an
    unexpected exception is reported in one line (set ``FREESTAND_DEBUG=1`` to
    see the traceback).
    """
    import os
    import warnings

    import numpy as np

    from freestand.cli.common import compile_notice

    args = list(sys.argv[1:] if argv is None else argv)
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            # numerical warnings (overflow in a record of absurd values...) are not
            # for the user: the inputs are checked, and the results carry a status
            warnings.simplefilter("ignore", RuntimeWarning)
            with compile_notice():
                result = app(args=args, prog_name="freestand", standalone_mode=False)
    except FreestandError as error:
        _print_error(str(error))
        return 2
    except KeyboardInterrupt:
        _print_error("interrupted")
        return 130
    except SystemExit as exit_:
        code = exit_.code
        return code if isinstance(code, int) else (0 if code is None else 1)
    except Exception as error:
        if _is_usage_error(error):
            value = _given_value(error, args)
            message = getattr(error, "message", None)
            if value is not None and isinstance(message, str) and repr(value) not in message:
                error.message = f"{message} (got {value!r})"
            error.show()
            return error.exit_code
        if type(error).__name__ == "Abort":
            _print_error("aborted")
            return 1
        if os.environ.get("FREESTAND_DEBUG"):
            raise
        _print_error(
            f"internal error ({type(error).__name__}: {error}); this is a defect of freestand, "
            "please report it with the command line (FREESTAND_DEBUG=1 shows the traceback)"
        )
        return 1
    return result if isinstance(result, int) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
