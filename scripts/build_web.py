"""Builds the browser page (`make web`) into a folder of static files, from the package registries only.

    python scripts/build_web.py [OUT]            (default build/web)

- Pyodide's runtime (CPython 3.14 compiled to WebAssembly) and MathJax come from npm
  (node_modules/, package-lock.json); the pure wheels of SymPy and mpmath from PyPI, at the versions
  requirements.txt pins; PyYAML has no pure wheel on PyPI, so its sdist is built without its C part;
  dhsym's own wheel is built from this checkout.
- Every wheel, and Pyodide's standard library (npm ships it as sources), is byte-compiled by
  Pyodide's own CPython (scripts/compile-wheels.js) and shipped without its .py files, SymPy without
  its test suites: the page imports without compiling (its cold start takes half as long).
- `pyodide/pyodide-lock.json` lists these four wheels only; the page loads nothing else, and
  nothing from the network: it works from `python -m http.server` in OUT and from any static host.

Downloads and the compiled third-party wheels are kept in build/web-cache/ between builds.
"""
from __future__ import annotations

import base64
import csv
import gzip
import hashlib
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CACHE = ROOT / "build" / "web-cache"
PYODIDE = ROOT / "node_modules" / "pyodide"
MATHJAX = ROOT / "node_modules" / "mathjax-full" / "es5" / "tex-svg.js"
# Pyodide's runtime: its loader as it is, and the WebAssembly and its JavaScript gzip-compressed
# (a quarter of their bytes; the page inflates them, so that any static host serves them small).
LOADER = "pyodide.mjs"
RUNTIME = ("pyodide.asm.mjs", "pyodide.asm.wasm")
# What the page's Python loads at start: the runtime, its saved state, and the zips of the modules not in it.
STARTS_WITH = [f"pyodide/{name}" for name in (LOADER, "pyodide-lock.json", *(f"{name}.gzip" for name in RUNTIME),
                                              "python.snapshot.gzip", "python_stdlib.zip", "site-packages.zip")]
PAGE_FILES = ("index.html", "style.css", "app.js", "page.js", "python.js", "editor.js", "results.js", "drawing.js",
              "worker.js")
# What the page never runs: SymPy's test suites and benchmarks (a third of its files).
LEFT_OUT = re.compile(r"(^|/)(tests|benchmarks)/")
COMPILED_STAMP = "compiled-5"  # change to recompile the cached third-party wheels


def main(out: Path) -> None:
    if not (PYODIDE / "pyodide.asm.wasm").exists() or not MATHJAX.exists():
        sys.exit("build_web: node_modules has no pyodide or mathjax-full; run scripts/ensure-node-packages.sh "
                 "(make web does)")
    pins = _pins()
    if out.exists():
        shutil.rmtree(out)
    (out / "pyodide").mkdir(parents=True)
    (out / "mathjax").mkdir()
    wheels, stdlib = _compiled(_third_party_wheels(pins) + [_dhsym_wheel()])
    with tempfile.TemporaryDirectory() as scratch:
        site = _site_zip(wheels, Path(scratch) / "site-packages.zip")
        modules = _modules_on_first_use(Path(scratch) / "modules.txt")
        _python_state(stdlib, site, modules, out / "pyodide")
    _write_lock(out / "pyodide" / "pyodide-lock.json")
    shutil.copy2(PYODIDE / LOADER, out / "pyodide" / LOADER)
    for name in RUNTIME:
        shutil.copy2(_gzipped(PYODIDE / name), out / "pyodide" / f"{name}.gzip")
    shutil.copy2(MATHJAX, out / "mathjax" / MATHJAX.name)
    for name in PAGE_FILES:
        shutil.copy2(ROOT / "web" / name, out / name)
    _write_robots(out / "robots.json")
    _write_manifest(out, wheels["dhsym"])


def _pins() -> dict:
    pins = {}
    for line in (ROOT / "requirements.txt").read_text().splitlines():
        match = re.match(r"([A-Za-z0-9_.-]+)==(\S+)", line)
        if match:
            pins[match.group(1).lower()] = match.group(2)
    return pins


def _pip(*args, env=None) -> None:
    result = subprocess.run([sys.executable, "-m", "pip", *args, "-q", "--disable-pip-version-check"],
                            capture_output=True, text=True, env=env)
    if result.returncode:
        sys.exit(f"build_web: pip {' '.join(args)} failed:\n{result.stderr[-3000:]}")


def _third_party_wheels(pins: dict) -> list[Path]:
    downloads = CACHE / "downloads"
    downloads.mkdir(parents=True, exist_ok=True)
    wheels = []
    for name in ("sympy", "mpmath"):
        found = list(downloads.glob(f"{name}-{pins[name]}-py3-none-any.whl"))
        if not found:
            _pip("download", "--no-deps", "--only-binary", ":all:", "-d", str(downloads), f"{name}=={pins[name]}")
            found = list(downloads.glob(f"{name}-{pins[name]}-py3-none-any.whl"))
        wheels += found
    return wheels + [_pure_pyyaml(pins["pyyaml"], downloads)]


def _pure_pyyaml(version: str, downloads: Path) -> Path:
    """PyYAML's pure-Python wheel, built from its sdist without the libyaml C extension."""
    wheel = downloads / f"pyyaml-{version}-py3-none-any.whl"
    if not wheel.exists():
        _pip("download", "--no-deps", "--no-binary", ":all:", "-d", str(downloads), f"PyYAML=={version}")
        sdist = next(downloads.glob(f"[pP]y[yY][aA][mM][lL]-{version}.tar.gz"))
        _pip("wheel", "--no-deps", "-w", str(downloads), str(sdist), env={**os.environ, "PYYAML_FORCE_LIBYAML": "0"})
    if not wheel.exists():
        sys.exit(f"build_web: building PyYAML {version} without its C part gave no {wheel.name}")
    print(f"build_web: PyYAML has no pure-Python wheel on PyPI: {wheel.name} is built from its sdist without the "
          "libyaml C extension (PYYAML_FORCE_LIBYAML=0); the page reads robot files with PyYAML's pure-Python "
          "SafeLoader, as dhsym always does")
    return wheel


def _dhsym_wheel() -> Path:
    target = CACHE / "dhsym-wheel"
    shutil.rmtree(target, ignore_errors=True)
    _pip("wheel", "--no-deps", "-w", str(target), str(ROOT))
    return next(target.glob("dhsym-*.whl"))


def _compiled(wheels: list[Path]) -> tuple[dict, Path]:
    """Each wheel byte-compiled and without its .py files (third-party ones kept in the cache):
    {package name: wheel path}; and Pyodide's standard library, which npm ships as sources."""
    compiled = CACHE / COMPILED_STAMP
    compiled.mkdir(exist_ok=True)
    stdlib = compiled / f"python_stdlib-{_pyodide_version()}.zip"
    to_compile = [w for w in wheels if w.name.startswith("dhsym-") or not (compiled / w.name).exists()]
    if to_compile or not stdlib.exists():
        with tempfile.TemporaryDirectory() as scratch:
            trees = {wheel.stem: (wheel, compiled / wheel.name) for wheel in to_compile}
            if not stdlib.exists():
                trees["stdlib"] = (PYODIDE / "python_stdlib.zip", stdlib)
            for name, (archive, _) in trees.items():
                with zipfile.ZipFile(archive) as opened:
                    for member in opened.namelist():
                        if not LEFT_OUT.search(member):
                            opened.extract(member, Path(scratch) / name)
            result = subprocess.run(["node", str(ROOT / "scripts" / "compile-wheels.js"), scratch],
                                    capture_output=True, text=True, cwd=ROOT)
            if result.returncode:
                sys.exit(f"build_web: byte-compiling failed:\n{result.stderr[-3000:]}")
            version, count = result.stdout.split()
            print(f"build_web: byte-compiled {count} modules with Pyodide's CPython {version}")
            for name, (_, target) in trees.items():
                _pack(Path(scratch) / name, target, record=name != "stdlib")
    return {_package_name(wheel.name): compiled / wheel.name for wheel in wheels}, stdlib


def _site_zip(wheels: dict, path: Path) -> Path:
    """The page's packages as one zip that Python imports from (zipimport): the compiled wheels'
    modules and data, without their metadata (the page installs nothing)."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED, compresslevel=9) as site:
        for wheel in wheels.values():
            with zipfile.ZipFile(wheel) as opened:
                for info in opened.infolist():
                    if ".dist-info/" not in info.filename:
                        site.writestr(info, opened.read(info), compress_type=zipfile.ZIP_DEFLATED, compresslevel=9)
    return path


# Every output of the page once, natively (the same pure-Python code as in the page): the modules of
# the page's packages that are imported on first use, not by `import dhsym.web.app`.
FIRST_USE = """
import json, sys
from pathlib import Path
from dhsym.web.app import handle
before = set(sys.modules)
robot = Path("dhsym/robots/planar2r.yaml").read_text("utf-8")
for request in [{"kind": "show", "show": show} for show in ("table", "links", "fk", "jacobian", "ik")] + [
        {"kind": "draw", "values": {}}, {"kind": "slides", "jacobian": True, "ik": True}]:
    answer = json.loads(handle(json.dumps({**request, "yaml": robot, "file": "planar2r.yaml", "width": 700})))
    assert answer["state"] == "ready", answer
packages = ("dhsym", "sympy", "mpmath", "yaml")
print("\\n".join(sorted(m for m in set(sys.modules) - before if m.split(".")[0] in packages)))
"""


def _modules_on_first_use(path: Path) -> Path:
    result = subprocess.run([sys.executable, "-c", FIRST_USE], capture_output=True, text=True, cwd=ROOT)
    if result.returncode:
        sys.exit(f"build_web: working out the page's outputs natively failed:\n{result.stderr[-3000:]}")
    path.write_text(result.stdout)
    return path


def _python_state(stdlib: Path, site: Path, modules: Path, out: Path) -> None:
    """The Python state the page restores (SymPy and dhsym imported), and the modules left to import
    from the zips (scripts/snapshot-python.js)."""
    result = subprocess.run(["node", str(ROOT / "scripts" / "snapshot-python.js"), str(stdlib), str(site),
                             str(modules), str(out)], capture_output=True, text=True, cwd=ROOT)
    if result.returncode:
        sys.exit(f"build_web: making the Python state failed:\n{result.stderr[-3000:]}")
    summary = json.loads(result.stdout.splitlines()[-1])
    print(f"build_web: Python's state with {summary['modules']} modules imported ({summary['memory'] / 1e6:.1f} MB "
          f"of memory), saved in pyodide/python.snapshot.gzip; the zips hold the modules not imported")


def _gzipped(path: Path) -> Path:
    """The file gzip-compressed, kept in the cache (the same bytes each time)."""
    target = CACHE / f"runtime-{_pyodide_version()}" / f"{path.name}.gzip"
    if not target.exists():
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(gzip.compress(path.read_bytes(), compresslevel=9, mtime=0))
    return target


def _pyodide_version() -> str:
    return json.loads((PYODIDE / "package.json").read_text())["version"]


def _package_name(wheel_name: str) -> str:
    return wheel_name.split("-")[0].lower().replace("_", "-")


def _pack(tree: Path, archive_path: Path, record: bool = True) -> None:
    """The tree as a zip (a wheel, with a RECORD of what it holds, if `record`): .pyc instead of .py,
    the same bytes each time."""
    files = sorted(p for p in tree.rglob("*") if p.is_file() and p.suffix != ".py" and p.name != "RECORD")
    record_name = next(p for p in tree.glob("*.dist-info")).name + "/RECORD" if record else None
    rows = []
    with zipfile.ZipFile(archive_path, "w", zipfile.ZIP_DEFLATED, compresslevel=9) as archive:
        for path in files:
            name = path.relative_to(tree).as_posix()
            data = path.read_bytes()
            archive.writestr(zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0)), data,
                             compress_type=zipfile.ZIP_DEFLATED, compresslevel=9)
            digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            rows.append([name, f"sha256={digest}", len(data)])
        if record_name:
            text = io.StringIO()
            csv.writer(text, lineterminator="\n").writerows(rows + [[record_name, "", ""]])
            archive.writestr(zipfile.ZipInfo(record_name, date_time=(2020, 1, 1, 0, 0, 0)), text.getvalue(),
                             compress_type=zipfile.ZIP_DEFLATED)


def _write_lock(path: Path) -> None:
    """A lock file of the page's own: Pyodide's runtime facts, and no packages (the page installs
    none: they are in its Python state and site-packages.zip)."""
    info = json.loads((PYODIDE / "pyodide-lock.json").read_text())["info"]
    path.write_text(json.dumps({"info": info, "packages": {}}, indent=1) + "\n")


def _write_robots(path: Path) -> None:
    sys.path.insert(0, str(ROOT))
    from dhsym.web.app import builtin_robots

    path.write_text(json.dumps(builtin_robots(), ensure_ascii=False))


def _write_manifest(out: Path, dhsym_wheel: Path) -> None:
    """build.json: the bytes of each file the page loads at start, for its progress bar; and a summary."""
    sizes = {name: (out / name).stat().st_size for name in STARTS_WITH}
    manifest = {"pyodide": _pyodide_version(), "dhsym": dhsym_wheel.name.split("-")[1], "files": sizes,
                "mathjax": (out / "mathjax" / MATHJAX.name).stat().st_size}
    (out / "build.json").write_text(json.dumps(manifest, indent=1) + "\n")
    everything = sorted(p for p in out.rglob("*") if p.is_file())
    total = sum(p.stat().st_size for p in everything)
    zipped = sum(len(gzip.compress(p.read_bytes(), 6)) for p in everything)
    for name, size in sizes.items():
        print(f"  {size / 1e6:7.2f} MB  {name}")
    shown = out.relative_to(ROOT) if out.is_relative_to(ROOT) else out
    print(f"build_web: {shown}: {len(everything)} files, {total / 1e6:.1f} MB ({zipped / 1e6:.1f} MB gzipped); "
          f"serve the folder, e.g. `python3 -m http.server -d {shown}`")


if __name__ == "__main__":
    main(Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else ROOT / "build" / "web")
