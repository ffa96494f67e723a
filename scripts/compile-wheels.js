#!/usr/bin/env node
// Byte-compiles the Python files under a folder with the very interpreter the browser page runs:
// Pyodide's own CPython, from node_modules, with the folder mounted into its file system. A .pyc is
// valid only for the CPython version that wrote it, so the page's Python must write them; the
// browser then imports them without compiling (half the page's cold start, see docs/web.md).
//
//     node scripts/compile-wheels.js build/web-cache/unpacked
//
// Each foo.py gets a foo.pyc beside it (the sourceless layout, which imports without its .py); the
// build (scripts/build_web.py) then drops the .py files and packs the wheels again. The header holds
// a hash instead of a time stamp, so that the same sources give the same bytes. Prints the Python
// version and the count of files compiled.
"use strict";
const path = require("path");
const { loadPyodide } = require("pyodide");

const COMPILE = `
import pathlib, py_compile, sys
root = pathlib.Path("/tree")
count = 0
for source in sorted(root.rglob("*.py")):
    relative = source.relative_to(root)
    shown = "/".join(relative.parts[1:])  # the path a traceback names: the wheel's own, e.g. sympy/core/basic.py
    py_compile.compile(str(source), cfile=str(source) + "c", dfile=shown, doraise=True,
                       invalidation_mode=py_compile.PycInvalidationMode.UNCHECKED_HASH)
    count += 1
f"{sys.version.split()[0]} {count}"
`;

async function main() {
  const folder = process.argv[2];
  if (!folder) {
    console.error("usage: node scripts/compile-wheels.js FOLDER");
    process.exit(2);
  }
  const indexURL = path.dirname(require.resolve("pyodide/package.json")) + path.sep;
  const pyodide = await loadPyodide({ indexURL, stdout: () => {}, stderr: (line) => console.error(line) });
  pyodide.FS.mkdir("/tree");
  pyodide.FS.mount(pyodide.FS.filesystems.NODEFS, { root: path.resolve(folder) }, "/tree");
  console.log(pyodide.runPython(COMPILE));
}

main().catch((error) => {
  console.error(`compile-wheels: ${error.message}`);
  process.exit(1);
});
