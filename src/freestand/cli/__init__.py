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
)


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


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status."""
    try:
        # without standalone mode click returns a typer.Exit's code instead of raising it
        status = app(args=argv, prog_name="freestand", standalone_mode=False)
    except FreestandError as error:
        from rich.console import Console
        from rich.markup import escape

        Console(stderr=True, highlight=False, soft_wrap=True).print(
            f"[bold red]error:[/] {escape(str(error))}", markup=True
        )
        return 2
    except typer.Exit as exit_:
        return exit_.exit_code
    except SystemExit as exit_:  # click's own usage errors
        return int(exit_.code or 0)
    except Exception as error:  # click.ClickException and friends
        import click

        if isinstance(error, click.ClickException):
            error.show()
            return error.exit_code
        if isinstance(error, click.exceptions.Abort):
            return 1
        raise
    return status if isinstance(status, int) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
