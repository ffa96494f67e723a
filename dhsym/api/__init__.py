"""The surface a notebook or a script uses, above every layer it calls: the notebook `Robot`
(`robot.fk()`, `.transform(3, 6)`, `.jacobian()`, `.ik()` and its Jupyter display, frames numbered
as the robot file prints them), `dhsym.show`, and the `dhsym` functions (`dhsym.load`, `fk`,
`jacobian`, `convert`, `check`, `screws`, `import_urdf`, `ik`).

Only this package, the command line and the web page translate printed numbers, through the
robot's `Numbering` (dhsym.core.numbering); the layers below work on plain chains, frames 0..n.
Nothing is imported here, so that `import dhsym` stays light: `dhsym/__init__` imports each name
on first use.
"""
