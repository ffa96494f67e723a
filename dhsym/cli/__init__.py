"""The `dhsym` command line: `main` parses and dispatches; each command is a module here with
`add_parsers(commands)` and `run(robot, args)`. `main` is imported on first use, so that the
`dhsym` process (`__main__.run`) can set up the garbage collector before SymPy is imported."""

__all__ = ["main"]


def __getattr__(name: str):
    if name == "main":
        from .app import main

        return main
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
