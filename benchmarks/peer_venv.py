"""A peer tool installed once into its own venv under build/peers/, so that a benchmark can time it
in a process of its own without putting it in dhsym's requirements.

>>> peer_python(Path("/nonexistent/peers/x"), "x==1", install=False)
(None, 'not installed (run without --no-install to install it into /nonexistent/peers/x)')
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def peer_python(venv: Path, package: str, install: bool) -> tuple[Path | None, str]:
    """The venv's python, installing `package` there when allowed (once: a .ready mark); or None and
    the reason, in one line."""
    python, ready = venv / "bin" / "python", venv / ".ready"
    if ready.exists():
        return python, ""
    if not install:
        return None, f"not installed (run without --no-install to install it into {venv})"
    print(f"installing {package} into {venv} (once) ...", flush=True)
    try:
        subprocess.run([sys.executable, "-m", "venv", "--clear", str(venv)], check=True, capture_output=True)
        subprocess.run([str(python), "-m", "pip", "install", "-q", "--disable-pip-version-check", package],
                       check=True, capture_output=True, timeout=1800)
    except (subprocess.SubprocessError, OSError) as error:
        reason = (getattr(error, "stderr", b"") or b"").decode(errors="replace").strip().splitlines()[-1:]
        return None, f"could not be installed: {(reason or [str(error)])[0]}"
    ready.touch()
    return python, ""
