"""The surface a notebook or a script uses, above every layer it calls (`robot.ik()`: dhsym.api.ik).
Only this package, the command line and the web page translate printed numbers; the layers below
work on plain chains, frames 0..n."""
