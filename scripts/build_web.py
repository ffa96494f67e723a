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
RUNTIME = ("pyodide.mjs", "pyodide.asm.mjs", "pyodide.asm.wasm")  # and python_stdlib.zip, byte-compiled
PAGE_FILES = ("index.html", "style.css", "app.js", "page.js", "python.js", "editor.js", "results.js", "drawing.js",
              "worker.js")
# What the page never runs: SymPy's test suites and benchmarks (a third of its files).
LEFT_OUT = re.compile(r"(^|/)(tests|benchmarks)/")
# Each wheel of the page: its PyPI name, the modules it provides, and what it needs.
PACKAGES = {"sympy": (["sympy"], ["mpmath"]), "mpmath": (["mpmath"], []), "pyyaml": (["yaml"], []),
            "dhsym": (["dhsym"], ["sympy", "pyyaml", "mpmath"])}
COMPILED_STAMP = "compiled-4"  # change to recompile the cached third-party wheels


def main(out: Path) -> None:
    if not (PYODIDE / "pyodide.asm.wasm").exists() or not MATHJAX.exists():
        sys.exit("build_web: node_modules has no pyodide or mathjax-full; run scripts/ensure-node-packages.sh "
                 "(make web does)")
    pins = _pins()
    if out.exists():
        shutil.rmtree(out)
    (out / "pyodide").mkdir(parents=True)
    (out / "mathjax").mkdir()
    wheels = _third_party_wheels(pins) + [_dhsym_wheel()]
    shipped = _compiled(wheels, out / "pyodide")
    _write_lock(shipped, out / "pyodide" / "pyodide-lock.json")
    for name in RUNTIME:
        shutil.copy2(PYODIDE / name, out / "pyodide" / name)
    shutil.copy2(MATHJAX, out / "mathjax" / MATHJAX.name)
    for name in PAGE_FILES:
        shutil.copy2(ROOT / "web" / name, out / name)
    _write_robots(out / "robots.json")
    _write_manifest(out, shipped)


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


def _compiled(wheels: list[Path], out: Path) -> dict:
    """Each wheel byte-compiled and without its .py files (third-party ones from the cache), in `out`:
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
    shutil.copy2(stdlib, out / "python_stdlib.zip")
    shipped = {}
    for wheel in wheels:
        shutil.copy2(compiled / wheel.name, out / wheel.name)
        shipped[_package_name(wheel.name)] = out / wheel.name
    return shipped


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


def _write_lock(shipped: dict, path: Path) -> None:
    """A lock file of the page's own: Pyodide's runtime facts, and the four local wheels."""
    info = json.loads((PYODIDE / "pyodide-lock.json").read_text())["info"]
    packages = {}
    for name, wheel in shipped.items():
        imports, depends = PACKAGES[name]
        packages[name] = {"name": name, "version": wheel.name.split("-")[1], "file_name": wheel.name,
                          "install_dir": "site", "sha256": hashlib.sha256(wheel.read_bytes()).hexdigest(),
                          "package_type": "package", "imports": imports, "depends": depends,
                          "unvendored_tests": False, "shared_library": False}
    path.write_text(json.dumps({"info": info, "packages": packages}, indent=1) + "\n")


def _write_robots(path: Path) -> None:
    sys.path.insert(0, str(ROOT))
    from dhsym.web.app import builtin_robots

    path.write_text(json.dumps(builtin_robots(), ensure_ascii=False))


def _write_manifest(out: Path, shipped: dict) -> None:
    """build.json: the bytes of each file the page loads at start, for its progress bar; and a summary."""
    loads = [f"pyodide/{name}" for name in RUNTIME] + ["pyodide/python_stdlib.zip", "pyodide/pyodide-lock.json"]
    loads += [f"pyodide/{wheel.name}" for wheel in shipped.values()]
    sizes = {name: (out / name).stat().st_size for name in loads}
    manifest = {"pyodide": _pyodide_version(), "dhsym": shipped["dhsym"].name.split("-")[1], "files": sizes,
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
